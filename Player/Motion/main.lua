-- The motion process: once per DCM tick, on the robot's clock, read the sensors, run the motion
-- state machine (Player/Motion/control.lua) and write joint commands and hardness. Takes part in
-- the sim's lockstep (each tick is finished before the DCM steps). `./run_main motion` starts it
-- alone; `luajit Player/Motion/main.lua [--initial STATE]` with the env of Run/env.sh too.
--
-- Inputs through the `motion` shm block (Lib/Motion.lua, Lib/Walk.lua): request/request_seq and
-- request_arg (a request's argument: the pattern's file), velocity, head_command, kick_* (a kick out
-- of the walk: Walk.kick; out: kick_ack, kick_phase, kicks), param_* (walk parameter changes and
-- config re-reads), taken and
-- taken_command (joints a caller took with Body.set_command & co.: written with the caller's
-- command until Body.release or a request whose state owns them). Outputs: state, walking, fallen,
-- falls, fall_time, odometry, walk_velocity, the walk's COM, ZMP, feet and capture error, zmp and
-- zmp_contact (balance), pattern_time (the state pattern's time in its file), owner (per joint: 0
-- held, 1 motion, 2 a caller), tick.
-- Only the joints the current state owns (or a caller took) are written: the others hold whatever
-- the actuator block has (Player/Motion/control.lua). A joint in torque mode (Body.set_torque) is
-- not written at all: its caller's torque drives it. A state drives a joint in torque mode by
-- setting ctl.tau[i] (N m) each tick (Body.drive_torque); one it stops setting goes back to
-- position mode holding where it is.
local ffi = require('ffi')
local shm = require('shm')
local Config = require('Config')
local Body = require('Body')
local lockstep = require('lockstep')
local Motion = require('Motion')
local WalkAPI = require('Walk')
local kin = require('kinematics')
local control = require('Motion.control')
local walkgen = require('Motion.walk')
local walk_kick = require('Motion.walk_kick')
local param = require('param')

ffi.cdef [[ int getpid(void); ]]

local args = { ... }
local initial
for i = 1, #args do
  if args[i] == '--initial' then initial = args[i + 1] end
end

local robot = Config.load('robot')
local params = Config.load('walk')
initial = initial or params.initialState

local ctl = control.new({ robot = robot, params = params, model = kin.load(), initial = initial,
  walk_files = table.concat(Config.files('walk'), ' + ') })
if initial == 'relax' or initial == 'sit' then ctl.want = initial end
local n = ctl.n
ctl.tau = {}            -- a state's torques this tick (joint index -> N m), consumed below
local torque_driven = {}   -- the joints motion put in torque mode

local sensor, actuator = Body.sensor, Body.actuator
local motion = shm.open('motion')

-- start from what the actuators hold now (no jump when the process restarts), every joint released
for i = 1, n do
  ctl.q[i] = actuator.command[i - 1]
  ctl.h[i] = actuator.hardness[i - 1]
end
motion:write(function(m)
  for i = 0, n - 1 do m.taken[i], m.owner[i] = 0, 0 end
end)

-- requests already in the block were made to the previous motion process: this one starts from
-- its initial state, and the behavior asks again once it sees the new pid (Player/Behavior/act.lua),
-- so the pid is published only after the request counter is read (a request in between is repeated)
local my_pid = ffi.C.getpid()
local last_request = motion.request_seq[0]
motion.pid[0] = my_pid
local last_param = motion.param_seq[0]
local last_kick = motion.kick_seq[0]

-- A kick out of the walk from the motion block (Lib/Walk.lua Walk.kick): the ball given in the
-- robot frame goes into the walk's ground frame through the torso's pose now.
local function apply_kick()
  local kind, foot = motion.kick_request[0], motion.kick_request[1]
  if kind == 0 then ctl.walk_kick:cancel() return end
  local ball
  if motion.kick_ball[2] ~= 0 then
    local w = ctl.walk
    ball = walkgen.pose_global({ motion.kick_ball[0], motion.kick_ball[1], 0 },
      { w.torso_x or w.uTorso[1], w.torso_y or w.uTorso[2], w.uTorso[3] })
  end
  local ok, err = ctl.walk_kick:request(walk_kick.KIND_NAMES[kind], foot == 0 and 'left' or 'right',
    ball, ctl.t)
  if not ok then io.stderr:write('motion: ', err, '\n') end
end

-- Applies a walk parameter change or a config re-read from the motion block.
local function apply_param()
  local name = ffi.string(motion.param_name, 64):gsub('%z.*$', '')
  local status = 0
  if name == '' then
    Config.reload()
    local ok, fresh = pcall(Config.load, 'walk')
    if ok then
      for k, v in pairs(fresh) do rawset(params, k, v) end
    else
      io.stderr:write('motion: walk config reload failed: ', tostring(fresh), '\n')
      status = -3
    end
  else
    local count = motion.param_count[0]
    local value
    if count == 1 then value = motion.param_value[0]
    else
      value = {}
      for i = 1, math.max(0, math.min(count, 4)) do value[i] = motion.param_value[i - 1] end
    end
    local values, code = WalkAPI.check(params, name, value)
    if values then
      local parent, key, cur = WalkAPI.lookup(params, name)
      if type(cur) == 'number' then rawset(parent, key, values[1])
      else for i = 1, #values do cur[i] = values[i] end end
    else
      status = code
    end
  end
  motion.param_status[0] = status
  motion.param_ack[0] = motion.param_seq[0]
end

-- every Config value live (Lib/param.lua): the changes made from the REPL land here once per tick
local params_live = param.follow('motion')

local participant = lockstep.join()
local tick = -1 -- the current tick is handled first (the lockstep waits for it)
local pos, gyro, angle, acc, ft, press = ctl.pos, ctl.gyro, ctl.angle, ctl.acc, ctl.ft, ctl.press
local hardness, actuator_mode = actuator.hardness, actuator.mode

-- a DCM restarted with another layout, or any block removed or recreated: the mappings held here
-- are dead; exit naming the block, and run_main starts a fresh process that opens what is there now
local check_blocks = require('shm_watch').exit_on_replaced('motion')
-- whole-body control's targets and status (the state wbc)
local wbc_link = require('Motion.wbc_link').new(shm.open('wbc'))
-- teleoperation's trajectories, commands and heartbeat (the state teleop)
local teleop_link = require('Motion.teleop_link')
teleop_link = teleop_link.new(shm.open('teleop'), shm.open('teleop.chunk'),
  Config.load('teleop', nil, { robot = robot.name }).executor.link_timeout, teleop_link.bounds(robot))

-- A fault for Tests/fault/faults_test.sh: with $HRP_FAULT_BUSY naming a file, motion loops for ever
-- (running, answering nothing: the hung writer the DCM's stall check catches) once the file appears.
-- It removes the file first, so the motion run_main starts in its place runs normally.
local busy_file = os.getenv('HRP_FAULT_BUSY')
local function busy_fault()
  if busy_file and os.remove(busy_file) then
    local x = 0
    while true do x = x + 1 end
  end
end

while true do
  local t = Body.wait_tick(tick, 1.0)
  check_blocks()
  if t then
    tick = t
    -- sensors (one consistent snapshot)
    local time = sensor:read(function(s)
      for i = 1, n do pos[i] = s.position[i - 1] end
      gyro[1], gyro[2], gyro[3] = s.gyro[0], s.gyro[1], s.gyro[2]
      angle[1], angle[2], angle[3] = s.angle[0], s.angle[1], s.angle[2]
      acc[1], acc[2], acc[3] = s.accelerometer[0], s.accelerometer[1], s.accelerometer[2]
      for k = 1, 24 do ft[k] = s.ft[k - 1] end
      for k = 1, #press do press[k] = s.foot_pressure[k - 1] end
      return s.time[0]
    end)
    -- what others did to the joints motion does not drive, and which joints a caller took
    ctl:sync(actuator.command, hardness, motion.taken, motion.taken_command)
    -- requests (each releases the joints its state owns) and parameters
    if motion.request_seq[0] ~= last_request then
      last_request = motion.request_seq[0]
      local s = Motion.STATES[motion.request[0] + 1]
      local arg = ffi.string(motion.request_arg, 256):gsub('%z.*$', '')
      for name, state in pairs(Motion.REQUESTS) do
        if state == s then
          local ok, err = ctl:request(name, { file = arg })
          if ok then
            for _, i in ipairs(ctl:needs(name)) do motion.taken[i - 1], ctl.taken[i] = 0, false end
          elseif err then
            io.stderr:write('motion: ', err, '\n')
          end
        end
      end
    end
    params_live:poll()
    if motion.param_seq[0] ~= last_param then
      last_param = motion.param_seq[0]
      apply_param()
    end
    if motion.kick_seq[0] ~= last_kick then
      last_kick = motion.kick_seq[0]
      apply_kick()
      motion.kick_ack[0] = last_kick
    end
    local v = ctl.vel_cmd
    v[1], v[2], v[3] = motion.velocity[0], motion.velocity[1], motion.velocity[2]
    ctl.head[1], ctl.head[2] = motion.head_command[0], motion.head_command[1]
    wbc_link:before(ctl)
    teleop_link:before(ctl)
    ctl:tick(time)
    wbc_link:after(ctl, tick)
    teleop_link:after(ctl, tick)
    -- commands of the joints motion drives now (Body clamps to the limits and refuses NaN)
    local q, write = ctl.q, ctl.write
    for i = 1, n do
      if actuator_mode[i - 1] ~= 0 then
        -- torque mode: the caller's hold follows the joint, so a return to position mode (the DCM's
        -- guard on a trip) is not undone by an older command
        if motion.taken[i - 1] ~= 0 then motion.taken_command[i - 1] = pos[i] end
      elseif write[i] then
        Body.drive(i, q[i])
        local h = ctl.h[i]
        if hardness[i - 1] ~= h then Body.set_hardness(i, h) end
      end
    end
    -- the state's torques: a refused one (NaN) puts the joint back in position mode, holding
    local tau = ctl.tau
    for i = 1, n do
      local nm = tau[i]
      if nm ~= nil then
        tau[i] = nil
        torque_driven[i] = Body.drive_torque(i, nm) or nil
        if not torque_driven[i] then Body.drive_torque(i, nil) end
      elseif torque_driven[i] then
        torque_driven[i] = nil
        Body.drive_torque(i, nil)
      end
    end
    -- the DCM's watchdog: a new tick_ack each tick, and the writer's pid so that its death is seen
    -- at once (Modules/dcm/guard.c), not only after the tick_ack timeout
    actuator.writer_pid[0] = my_pid
    actuator.tick_ack[0] = tick
    local w = ctl.walk
    motion:write(function(m)
      m.state[0] = ctl:state_index()
      m.walking[0] = w:is_active() and 1 or 0
      m.fallen[0] = (ctl:state() == 'falling' or ctl:state():match('^standup')) and 1 or 0
      m.falls[0] = ctl.falls
      m.fall_time[0] = ctl.fall_time
      m.odometry[0], m.odometry[1], m.odometry[2] = w.uTorso[1], w.uTorso[2], w.uTorso[3]
      m.walk_velocity[0], m.walk_velocity[1], m.walk_velocity[2] = w.vel[1], w.vel[2], w.vel[3]
      m.walk_com[0], m.walk_com[1], m.walk_zmp[0], m.walk_zmp[1] = w.com[1], w.com[2], w.zmp[1], w.zmp[2]
      m.walk_feet[0], m.walk_feet[1], m.walk_feet[2] = w.uLeft[1], w.uLeft[2], w.uLeft[3]
      m.walk_feet[3], m.walk_feet[4], m.walk_feet[5] = w.uRight[1], w.uRight[2], w.uRight[3]
      local e = ctl.capture.err
      m.capture_error[0], m.capture_error[1] = e and e[1] or 0, e and e[2] or 0
      m.walk_steps[0], m.steps_adjusted[0] = w.stats.steps, w.stats.adjusted or 0
      m.kick_phase[0], m.kicks[0] = ctl.walk_kick:phase(), ctl.walk_kick.count
      m.pattern_time[0] = ctl.pattern_time or -1
      local b = ctl.balance
      m.zmp[0], m.zmp[1], m.zmp[2], m.zmp[3] = b.zmp[1], b.zmp[2], w.zmp[1], w.zmp[2]
      m.zmp[4], m.zmp[5], m.zmp_contact[0] = b.shift[1], b.shift[2], b.contact and 1 or 0
      for i = 1, n do m.owner[i - 1] = ctl.owner[i] end
      m.tick[0] = tick
    end)
    participant:done(tick, tick + 1)
    busy_fault()
  end
end
