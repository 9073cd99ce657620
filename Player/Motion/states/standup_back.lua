-- standup_back: stand up from lying on the back (Config/<PLATFORM>/keyframes/standup_back.lua).
return require('Motion.states.standup').make('standup_back')
