-- standup_front: stand up from lying on the front (Config/<PLATFORM>/keyframes/standup_front.lua).
return require('Motion.states.standup').make('standup_front')
