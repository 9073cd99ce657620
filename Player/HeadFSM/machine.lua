-- The head's state machine: scan for the ball, track it, look at the goal now and then.
return {
  states = { 'scan', 'track', 'lookgoal' },
  initial = 'scan',
  transitions = {
    scan = { ball = 'track' },
    track = { lost = 'scan', timeout = 'lookgoal' },
    lookgoal = { done = 'track', lost = 'scan' },
    ['*'] = { reset = 'scan' },
  },
}
