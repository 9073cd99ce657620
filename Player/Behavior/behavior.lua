-- The behavior: reads vision and odometry, updates the world model, follows the game state and runs
-- the head and body machines; writes the world and game blocks.
--
--   local b = require('Behavior.behavior').new(opts)   -- opts.port: GameController port override,
--                                                      -- opts.fresh: ignore a predecessor's blocks,
--                                                      -- opts.team_port: team communication port
--   b:step()          -- one step at the current robot time
--   b:run()           -- the process's loop (lockstep-aware), until SIGTERM
local shm = require('shm')
local Config = require('Config')
local Body = require('Body')
local fsm = require('fsm')
local lockstep = require('lockstep')
local World = require('World.world')
local controller = require('GameFSM.controller')
local packet = require('GameFSM.packet')
local setplay = require('GameFSM.setplay')
local act = require('Behavior.act')
local Team = require('Team.team')
local roles = require('Team.roles')
local position = require('Team.position')
local param = require('param')
local netlog = require('netlog')

local M = {}

local function machine(which, initial)
  local def = require(which .. '.machine')
  return fsm.new({ name = which, states = def.states, transitions = def.transitions,
    initial = initial or def.initial, load = function(n) return require(which .. '.' .. n) end })
end

-- What a predecessor left in the world and game blocks, if it wrote them within cfg.resume.within
-- s of robot time `t` (a restarted process on a robot nobody carried; after a longer gap, or a
-- DCM restart that began the clock again, the robot starts afresh).
local function predecessor(blocks, cfg, t)
  local g, w = blocks.game, blocks.world
  local age = t - g.time[0]
  if g.time[0] <= 0 or age < 0 or age > cfg.resume.within then return nil end
  local r = { state = packet.STATES[g.state[0]], penalized = g.penalized[0] ~= 0 }
  local wage = t - w.time[0]
  if w.time[0] > 0 and wage >= 0 and wage <= cfg.resume.within then
    r.pose = { w.pose[0], w.pose[1], w.pose[2] }
  end
  return r.state and r or nil
end

local Behavior = {}
Behavior.__index = Behavior

function M.new(opts)
  opts = opts or {}
  local cfg = Config.load('behavior', {
    team_number = 'number', player_number = 'number',
    step_ticks = 'number', vision_stale_after = 'number', world = 'table', head = 'table', body = 'table',
    ready_pose = 'table', resume = { within = 'number', spread = 'number' },
  })
  local rules = Config.load('game', {
    gamecontroller = { port = 'number', return_port = 'number', alive_period = 'number',
      start_without = 'string', start_delay = 'number' },
    kickoff = { wait = 'number', distance = 'number', ball_moved = 'number' },
    setplay = { distance = 'table', margin = 'number', hysteresis = 'number', retreat_speed = 'number',
      turn_gain = 'number', take_tolerance = 'number', keeper_line = 'number' },
    team = { enabled = 'boolean', port_base = 'number', broadcast = 'string', period = 'number',
      lost_after = 'number', max_per_step = 'number', max_players = 'number' },
    roles = { enabled = 'boolean', goalkeeper = 'number', walk_speed = 'number', turn_speed = 'number',
      striker_margin = 'number', fallen_time = 'number', keeper_depth = 'number', keeper_clear = 'number',
      arrive = 'number', receive_ahead = 'number', receive_inside = 'number' },
  })
  local port = opts.port or tonumber(os.getenv('HRP_GC_PORT') or '') or nil
  local return_port = opts.return_port or tonumber(os.getenv('HRP_GC_RETURN_PORT') or '') or nil
  local gc = controller.new({ team_number = cfg.team_number, player_number = cfg.player_number,
    gamecontroller = rules.gamecontroller }, { port = port, return_port = return_port })
  if gc.socket_error then
    io.stderr:write('behavior: GameController disabled: ', gc.socket_error, '\n')
  end
  local team = Team.new({ team_number = cfg.team_number, player_number = cfg.player_number, team = rules.team },
    { port = opts.team_port or tonumber(os.getenv('HRP_TEAM_PORT') or '') or nil })
  if team.socket_error then
    io.stderr:write('behavior: team communication disabled: ', team.socket_error, '\n')
  end
  -- every datagram read, raw, into net.packets for the recorder
  local packets, perr = netlog.open()
  if packets then
    if gc.sock then gc.sock.tap = packets:tap(netlog.GAMECONTROLLER) end
    if team.sock then team.sock.tap = packets:tap(netlog.TEAM) end
  else
    io.stderr:write('behavior: received packets are not logged: ', perr, '\n')
  end
  -- the camera's half horizontal field of view: obstacles outside it are kept (World:update's view)
  local cam = Config.load('camera', { width = 'number', intrinsics = { fx = 'number' } })
  local view = { pan = 0, half_fov = math.atan(cam.width / 2 / cam.intrinsics.fx) }
  local wcfg = setmetatable({}, { __index = cfg.world })
  wcfg.seed = tonumber(os.getenv('HRP_SEED') or '') or cfg.world.seed
  local blocks = { world = shm.open('world'), game = shm.open('game'), vision = shm.open('vision'),
    motion = shm.open('motion'), team = shm.open('team') }
  local prev = not opts.fresh and predecessor(blocks, cfg, Body.get_time()) or nil
  local self = setmetatable({
    cfg = cfg, rules = rules, gc = gc, team = team, world = World.new(wcfg),
    body = machine('BodyFSM'), head = machine('HeadFSM'),
    game = machine('GameFSM', prev and (prev.penalized and 'penalized' or prev.state)),
    blocks = blocks, packets = packets, view = view, vision_time = -1, vision_time_changed = nil, steps = 0,
    resumed = prev,
  }, Behavior)
  if prev then
    gc:resume(prev.state, prev.penalized)
    if prev.pose then self.world:resume(prev.pose[1], prev.pose[2], prev.pose[3], cfg.resume.spread) end
  end
  self.ctx = { cfg = cfg, rules = rules, world = self.world, act = act, body = self.body,
    head = self.head, t = 0, game = gc:view() }
  return self
end

-- The vision block's detections as the world model wants them.
local posts = { {}, {} }
function Behavior:read_vision()
  local v = self.blocks.vision
  return v:read(function(b)
    local n = math.min(2, math.max(0, b.goal_posts[0]))
    local list = {}
    for k = 1, n do
      posts[k][1], posts[k][2] = b.goal_position[2 * k - 2], b.goal_position[2 * k - 1]
      list[k] = posts[k]
    end
    local robots = {}
    for k = 1, math.min(4, math.max(0, b.robots[0])) do
      robots[k] = { x = b.robot_position[2 * k - 2], y = b.robot_position[2 * k - 1], team = b.robot_team[k - 1],
        foot_visible = b.robot_foot_visible[k - 1] ~= 0 }
    end
    return {
      frame = b.frame[0], time = b.time[0], ball_detected = b.ball_detected[0] ~= 0,
      ball = { b.ball_position[0], b.ball_position[1] }, posts = list, robots = robots,
    }
  end)
end

function Behavior:step()
  local t = Body.get_time()
  local ctx = self.ctx
  ctx.t = t
  if self.packets then self.packets.t = t end
  local m = self.blocks.motion
  local odom = { m.odometry[0], m.odometry[1], m.odometry[2] }
  local vis = self:read_vision()
  -- vision freshness on the robot clock: the frame counter must keep moving
  if vis.frame ~= self.vision_frame then
    self.vision_frame = vis.frame
    self.vision_changed = t
  end
  self.vision_changed = self.vision_changed or t
  ctx.vision_stale = (t - self.vision_changed) > self.cfg.vision_stale_after
  local view = self.view
  view.pan = Body.get_head_position()[1]
  self.world:update(t, odom, vis, self.cfg.world.imu_yaw and Body.get_angle()[3] or nil, view)
  self.world:publish(self.blocks.world)
  self:talk(t, m)

  local state, penalized = self.gc:update(t, Body.get_button(1) ~= 0)
  ctx.game = self.gc:view()
  -- a kick-off: PLAYING right after SET (Player/GameFSM/playing.lua follows its progress)
  if state == 'playing' and self.last_state == 'set' then ctx.kickoff = { t0 = t } end
  if state ~= 'playing' then ctx.kickoff = nil end
  -- from a placement until the kick-off the robot is in its own half (the pose filter's side)
  if state == 'playing' then self.world.pose.own_half = false end
  self.last_state = state
  local want = penalized and 'penalized' or state
  if self.game:state() ~= want or not self.game.current then self.game:event(want, ctx) end
  self.game:update(ctx)

  local gc, g = self.gc, self.blocks.game
  g:write(function(b)
    b.state[0] = packet.STATE[state]
    b.penalized[0] = penalized and 1 or 0
    b.team_color[0] = gc.team_colour
    b.kickoff_team[0] = gc.kickoff_team
    b.score[0], b.score[1] = gc.score[1], gc.score[2]
    b.packets[0] = gc.packets
    b.bad_packets[0] = gc.bad_packets
    b.rejected[0] = gc.rejected
    b.secondary_state[0] = gc.secondary_state
    b.secondary_team[0], b.secondary_mode[0] = gc.secondary_team, gc.secondary_mode
    b.secondary_time[0] = gc.secondary_time
    b.goalkeeper[0] = gc.goalkeeper and 1 or 0
    b.returns[0] = gc.returns
    b.setplay[0] = setplay.INDEX[state == 'playing' and not penalized and ctx.setplay or 'play']
    b.role[0] = roles.INDEX[ctx.role or 'striker']
    b.body_state[0] = self.body:index()
    b.head_state[0] = self.head:index()
    b.time[0] = t
  end)
  self.steps = self.steps + 1
end

-- Team communication: our estimates out, teammates' into the world model (world.mates).
function Behavior:talk(t, m)
  local w, gc = self.world, self.gc
  local p = w.pose
  local ball
  if w:ball_known() then
    local bx, by = w:ball_field()
    local c, s = math.cos(p.a), math.sin(p.a)
    ball = { bx, by, c * w.ball.vx - s * w.ball.vy, s * w.ball.vx + c * w.ball.vy }
  end
  self.ctx.down = act.down()
  if self.rules.team.enabled then
    self.team:update(t, { pose = { p.x, p.y, p.a }, ball = ball, penalised = gc:penalized(), fallen = self.ctx.down,
      colour = gc.gc_seen and gc.team_colour or nil, target = self:target(ball),
      walk = { m.walk_velocity[0], m.walk_velocity[1], m.walk_velocity[2] } })
    w.mates = self.team:mates(t)
  else
    w.mates = {} -- team play off: nothing sent, nothing heard (the comparison's robots alone)
  end
  self.team:publish(self.blocks.team, t)
  self:assign_role()
end

-- Where this robot goes (field x, y, heading; the message's target_pose), from its last role: the
-- ball when it plays it (`ball`, the one it sends: teammates compare the two), its role's place
-- otherwise; nil without roles or a place.
function Behavior:target(ball)
  local ctx, rc = self.ctx, self.rules.roles
  if not (rc.enabled and ctx.role) then return nil end
  local x, y = position.target(ctx.role, ctx.team_ball, rc, self.world.cfg.field, ctx.clearing)
  if x then return { x, y, 0 } end
  local b = ball or ctx.team_ball
  return b and { b[1], b[2], 0 } or nil
end

-- This robot's role from the shared estimates (Player/Team/roles.lua); the striker alone or
-- without roles.
function Behavior:assign_role()
  local rc, ctx, w = self.rules.roles, self.ctx, self.world
  ctx.team_ball = w:shared_ball()
  if not rc.enabled then ctx.role, ctx.clearing = 'striker', false return end
  local keeper = self.gc.gc_seen and self.gc.goalkeeper_player or rc.goalkeeper
  self.role_cfg = self.role_cfg or setmetatable({}, { __index = rc })
  self.role_cfg.goalkeeper = keeper
  local p = w.pose
  ctx.role, ctx.roles, ctx.clearing = roles.assign({ player = self.cfg.player_number, pose = { p.x, p.y, p.a },
    fallen = ctx.down },
    w.mates, self.role_cfg, ctx.team_ball, -w.cfg.field.length / 2, ctx.roles, ctx.clearing)
end

-- Closes the sockets (tests; the process just ends).
function Behavior:close()
  self.gc:close()
  self.team:close()
end

-- The process loop: one step per `step_ticks` ticks, reporting to the lockstep. In lockstep a step
-- comes after motion and vision finished the tick (Lib/lockstep.lua's stages): it reads this tick's
-- odometry and detections, never a mix that depends on who ran first, so a run and its replay agree.
function Behavior:run()
  -- every Config value live (Lib/param.lua): the machines and the world model read their config at
  -- every step; the pose filter's particle count is re-derived
  local live = param.follow('behavior')
  live:on('behavior.world.pose.particles', function()
    local f = self.world.pose
    f.n = self.cfg.world.pose.particles
    f:init_prior()
  end)
  live:on('behavior.world.field', function()
    local fl = self.cfg.world.field
    local hx, hw = fl.length / 2, fl.goal_width / 2
    local real = self.world.pose.posts
    real[1][1], real[1][2], real[2][1], real[2][2] = hx, hw, hx, -hw
    real[3][1], real[3][2], real[4][1], real[4][2] = -hx, hw, -hx, -hw
  end)
  local participant = lockstep.join({ after = true })
  local tick = Body.get_tick()
  local wake = tick
  -- a block replaced under this process (removed, or recreated with another layout): exit, named,
  -- for run_main's restart
  local check_blocks = require('shm_watch').exit_on_replaced('behavior')
  while true do
    check_blocks()
    if tick >= wake or participant:due(tick) then
      participant:settle(tick)
      live:poll()
      self:step()
      wake = tick + math.max(1, math.floor(self.cfg.step_ticks))
      participant:done(tick, wake)
    end
    local t = Body.wait_tick(tick, 1.0)
    if t then tick = t end
  end
end

return M
