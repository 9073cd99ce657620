-- standup_back: stand up from lying on the back (Config/robots/<ROBOT>/keyframes/standup_back.lua).
return require('Motion.states.standup').make('standup_back')
