-- The simulator's truth and control (PLATFORM=Sim), through this robot's `sim` block.
--
--   local Sim = require('Sim')
--   Sim.truth()  --> { x, y, z, yaw, roll, pitch, fallen = bool, ball = { x, y, z, vx, vy, touch, touch_time },
--                      cop = { x, y, fz } }  (cop: the centre of pressure of the ground's forces on the
--                      soles, on the carpet's plane, and their normal sum; fz = 0 with no sole down)
--                    (ball.touch: world index of the robot that touched it last, -1 none since placed)
--   Sim.reset()                      every robot to its start pose, ball to the centre, score 0:0
--   Sim.teleport_robot(x, y, yaw)    this robot, joints at their commands, on its lower sole laid flat, at rest
--   Sim.teleport_ball(x, y [, vx, vy])
--   Sim.push(fx, fy, duration)       N on the torso, field frame, for duration s of robot time
--   Sim.push_link(name, fx, fy, fz, duration)  N at the origin of a link or frame of the body's URDF
--                                    ('r_palm'), field frame, for duration s; a name the body lacks
--                                    is an error naming it
--   Sim.press_button(i [, duration]) button i (1 or 2) held for duration s (default 0.1)
--   Sim.score()  --> goals into the goal at +x, goals into the goal at -x
--   Sim.link_truth(name)  --> { x, y, z, roll, pitch, yaw } of a link or frame of the body's URDF
--                    ('l_sole', 'camera_link', its root link, ...): field frame, R = Rz(yaw) Ry(pitch)
--                    Rx(roll) as Sim.truth's; a name the body lacks is an error naming it
--   Sim.link_names() --> the body's links (its root link first) and frames
--   Sim.of(id)   --> the same functions for robot `id` of this world (a referee: Tools/match/referee.lua)
--   Sim.use_robot(id)                Sim.* for robot `id` from now on (hardware in the loop: the
--                                    simulated robot behind a bus emulator has its own id)
--
-- Field frame: origin at the centre spot, x towards the goal at +x, y left, z up; metres, radians.
-- A request returns once the sim DCM has applied it (in lockstep mode: on the current tick, before
-- the next step), or nil and an error when no sim DCM answers.
local ffi = require('ffi')
local shm = require('shm')

local M = {}
local C = shm.C

local REQUEST = { reset = 1, teleport_robot = 2, teleport_ball = 3, push = 4, button = 5, link_truth = 6,
  push_link = 7 }
local TIMEOUT = 2.0   -- s of wall time to wait for the DCM

-- The blocks of robot `id` (nil: this process's robot). Requests wake this process's own sync
-- block too: a lockstep DCM waiting on this script's tick sees them at once.
local function make(id)
  local R = {}
  local sim, sync, own_sync, sensor
  local function blocks()
    if not sim then
      local opt = id and { robot = id } or nil
      sim = shm.open('sim', opt)
      sync = shm.open('sync', opt)
      own_sync = id and shm.open('sync') or sync
      sensor = shm.open('dcm.sensor', opt)
    end
    return sim
  end
  R.blocks = blocks

  -- Request `code` with args a..d; fill(x), if given, writes the request's other fields.
  function R.request(code, a, b, c, d, fill)
    local s = blocks()
    local pid = sensor.dcm_pid[0]
    if pid == 0 or C.shm_pid_alive(pid) == 0 then
      return nil, 'no sim DCM is running for robot ' .. (id or shm.robot_id()) .. ' (start ./run_dcm)'
    end
    local seq
    s:write(function(x)
      x.request[0] = code
      x.args[0], x.args[1], x.args[2], x.args[3] = a or 0, b or 0, c or 0, d or 0
      if fill then fill(x) end
      seq = x.request_seq[0] + 1
      x.request_seq[0] = seq
    end)
    -- a DCM in lockstep may be waiting on the participants: wake it
    for _, y in ipairs(own_sync == sync and { sync } or { sync, own_sync }) do
      C.shm_fetch_add_u32(y.done_count, 1)
      C.shm_futex_wake(y.done_count)
    end
    local done = ffi.cast('volatile uint32_t *', s.done_seq)
    local deadline = C.shm_now() + TIMEOUT
    while true do
      local d0 = done[0]
      if d0 == seq then return true end
      local left = deadline - C.shm_now()
      if left <= 0 then return nil, 'the sim DCM did not apply the request within ' .. TIMEOUT .. ' s' end
      C.shm_futex_wait(done, d0, math.min(left, 0.01))
    end
  end
  return R
end

local function finite(x) return type(x) == 'number' and x == x and x ~= math.huge and x ~= -math.huge end

local function check_numbers(fname, ...)
  for i = 1, select('#', ...) do
    local v = select(i, ...)
    if not finite(v) then
      error(string.format('Sim.%s: argument %d must be a finite number, got %s', fname, i, tostring(v)), 3)
    end
  end
end

-- The functions below, bound to one robot's blocks (R from make()).
local function bind(S, R)
  local blocks, request = R.blocks, R.request

  -- The robot's torso and the ball, field frame.
  function S.truth()
    local s = blocks()
    return s:read(function(x)
      return {
        x = x.robot[0], y = x.robot[1], z = x.robot[2],
        yaw = x.robot[3], roll = x.robot[4], pitch = x.robot[5],
        fallen = x.fallen[0] ~= 0,
        ball = { x = x.ball[0], y = x.ball[1], z = x.ball[2], vx = x.ball[3], vy = x.ball[4],
          touch = x.ball_touch[0], touch_time = x.ball_touch_time[0] },
        cop = { x = x.cop[0], y = x.cop[1], fz = x.cop[2] },
      }
    end)
  end

  function S.reset() return request(REQUEST.reset) end

  function S.teleport_robot(x, y, yaw)
    check_numbers('teleport_robot', x, y, yaw or 0)
    return request(REQUEST.teleport_robot, x, y, yaw or 0)
  end

  function S.teleport_ball(x, y, vx, vy)
    check_numbers('teleport_ball', x, y, vx or 0, vy or 0)
    return request(REQUEST.teleport_ball, x, y, vx or 0, vy or 0)
  end

  function S.push(fx, fy, duration)
    check_numbers('push', fx, fy, duration)
    if duration < 0 then error('Sim.push: duration must be >= 0', 2) end
    return request(REQUEST.push, fx, fy, duration)
  end

  function S.press_button(i, duration)
    if i ~= 1 and i ~= 2 then error('Sim.press_button: button must be 1 or 2', 2) end
    check_numbers('press_button', duration or 0.1)
    return request(REQUEST.button, i - 1, duration or 0.1)
  end

  -- Goals scored into the goal at +x and into the goal at -x.
  function S.score()
    local s = blocks()
    local plus, minus = s:read(function(x) return x.score[0], x.score[1] end)
    return plus, minus
  end

  function S.link_names()
    local s = blocks()
    local cap = s:count('link_names')
    local text = s:read(function(x)
      local n = 0
      while n < cap and x.link_names[n] ~= 0 do n = n + 1 end
      return ffi.string(x.link_names, n)
    end)
    local names = {}
    for n in text:gmatch('%S+') do names[#names + 1] = n end
    return names
  end

  -- A request about link or frame `name` (into link_name): link_truth or push_link.
  local function link_request(fname, name, kind, a1, a2, a3, a4)
    if type(name) ~= 'string' or name == '' or name:find('\0', 1, true) then
      error(string.format('Sim.%s: the name of a link or frame expected, got %q', fname, tostring(name)), 3)
    end
    local s = blocks()
    local cap = s:count('link_name')
    if #name >= cap then
      error(string.format("Sim.%s: '%s' is longer than the %d bytes a name may have", fname, name, cap - 1), 3)
    end
    return request(kind, a1, a2, a3, a4, function(x)
      ffi.fill(x.link_name, cap)
      ffi.copy(x.link_name, name, #name)
    end)
  end
  local function no_such_link(fname, name)
    local names = S.link_names()
    local some = {}
    for k = 1, math.min(#names, 8) do some[k] = names[k] end
    error(string.format("Sim.%s: the body has no link or frame '%s' (it has %d: %s%s)", fname, name, #names,
      table.concat(some, ', '), #names > #some and ', ...' or ''), 3)
  end

  function S.push_link(name, fx, fy, fz, duration)
    check_numbers('push_link', fx, fy, fz, duration)
    if duration < 0 then error('Sim.push_link: duration must be >= 0', 2) end
    local ok, err = link_request('push_link', name, REQUEST.push_link, fx, fy, fz, duration)
    if not ok then return nil, err end
    if blocks().link_status[0] ~= 0 then no_such_link('push_link', name) end
    return true
  end

  function S.link_truth(name)
    local s = blocks()
    local ok, err = link_request('link_truth', name, REQUEST.link_truth, 0, 0, 0, 0)
    if not ok then return nil, err end
    local status, pose = s:read(function(x)
      local p = x.link_pose
      return x.link_status[0], { x = p[0], y = p[1], z = p[2], roll = p[3], pitch = p[4], yaw = p[5] }
    end)
    if status == 2 then
      error(string.format("Sim.link_truth: the simulator's pose of '%s' is not finite", name), 2)
    elseif status ~= 0 then
      no_such_link('link_truth', name)
    end
    return pose
  end

  -- Simulated seconds per wall second, as measured by the DCM.
  function S.realtime_factor() return blocks().realtime_factor[0] end
  return S
end

bind(M, make(nil))
function M.of(id) return bind({}, make(id)) end
function M.use_robot(id)
  if type(id) ~= 'number' or id < 0 or id % 1 ~= 0 then error('Sim.use_robot: a robot id, got ' .. tostring(id), 2) end
  bind(M, make(id))
end

return M
