-- The body's state machine: search (turn, then wander), approach the ball, align behind it towards
-- the opponent goal, kick (or dribble), follow up; reposition when the ball is lost.
return {
  states = { 'idle', 'search', 'wander', 'approach', 'align', 'kick', 'follow', 'reposition', 'dribble' },
  initial = 'idle',
  transitions = {
    search = { ball = 'approach', timeout = 'wander' },
    wander = { ball = 'approach', timeout = 'search' },
    approach = { near = 'align', lost = 'reposition' },
    align = { far = 'approach', done = 'kick', dribble = 'dribble', lost = 'reposition' },
    dribble = { realign = 'approach', lost = 'reposition' },
    kick = { done = 'follow' },
    follow = { ball = 'approach', timeout = 'search' },
    reposition = { ball = 'approach', done = 'search' },
    ['*'] = { start = 'search', stop = 'idle' },
  },
}
