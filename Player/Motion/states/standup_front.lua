-- standup_front: stand up from lying on the front (Config/robots/<ROBOT>/keyframes/standup_front.lua).
return require('Motion.states.standup').make('standup_front')
