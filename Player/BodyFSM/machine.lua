-- The body's state machine: search (turn, then wander), approach the ball, align behind it towards
-- the opponent goal, kick (or dribble), follow up; reposition when the ball is lost; stand and
-- localize when the pose is not trusted before attacking by it. With the ball in the kick zone and
-- the goal in front (BodyFSM/shot.lua) approach, align and dribble shoot: a kick out of the walk. A ball
-- in a goal (scored) is not followed into it: wait.
return {
  states = { 'idle', 'search', 'wander', 'approach', 'align', 'kick', 'follow', 'reposition', 'dribble',
    'localize', 'wait' },
  initial = 'idle',
  transitions = {
    search = { ball = 'approach', timeout = 'wander' },
    wander = { ball = 'approach', timeout = 'search' },
    approach = { near = 'align', lost = 'reposition', unsure = 'localize', shoot = 'kick', in_goal = 'wait' },
    align = { far = 'approach', done = 'kick', dribble = 'dribble', lost = 'reposition', unsure = 'localize',
      shoot = 'kick', in_goal = 'wait' },
    dribble = { realign = 'approach', lost = 'reposition', unsure = 'localize', shoot = 'kick', in_goal = 'wait' },
    wait = { out = 'approach', lost = 'search' },
    localize = { done = 'approach' },
    kick = { done = 'follow' },
    follow = { ball = 'approach', timeout = 'search' },
    reposition = { ball = 'approach', done = 'search' },
    ['*'] = { start = 'search', stop = 'idle' },
  },
}
