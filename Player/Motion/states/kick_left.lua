-- kick_left: a kick with the left foot (Player/Motion/kick.lua), then stance.
return require('Motion.kick').state('left')
