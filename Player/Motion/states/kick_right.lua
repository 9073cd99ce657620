-- kick_right: a kick with the right foot (Player/Motion/kick.lua), then stance.
return require('Motion.kick').state('right')
