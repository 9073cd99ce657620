-- teleop: the executor of checked teleoperation trajectories (docs/teleoperation.md). A trajectory
-- (Lib/teleop.lua: joint angles at the control period, checked before it was sent) arrives in
-- chunks through Player/Motion/teleop_link.lua; a start command plays it only when it has arrived
-- whole with its checksum right, the operator's link is alive, and the robot stands at its first
-- sample (the executor config's start_tolerance). Pause holds at the sample being played, resume goes
-- on from it, stop holds and drops the trajectory: each at the tick the command arrives. On a lost
-- link (no heartbeat for link_timeout s) it holds at once or finishes the segment being played and
-- holds (on_lost); it never starts the next segment. Holding is commanding the last sample again.
-- Another motion asked for: the executor stops and leaves through stance.
local M = {}

M.owns = { 'all' }

local START, PAUSE, RESUME, STOP = 1, 2, 3, 4

local function config(c)
  c.teleop_cfg = c.teleop_cfg or require('Config').load('teleop', nil, { robot = c.robot.name }).executor
  return c.teleop_cfg
end

function M.entry(c)
  local d = c:scratch('teleop')
  d.report = d.report or {}
  local r = d.report
  r.state, r.sample, r.segment, r.reason = 'idle', 0, 0, ''
  d.traj, d.k, d.seg, d.finish_to = nil, 0, 0, nil
  c.teleop_report = r
end

local function answer(c, cmd, ok, err)
  c.teleop_done = { seq = cmd.seq, ok = ok, error = err }
end

-- The robot at the trajectory's first sample: the largest difference, rad, and its joint.
local function off_start(c, traj)
  local worst, at = 0, 1
  for i = 1, c.n do
    local e = math.abs(c.pos[i] - traj.q[1][i])
    if e > worst then worst, at = e, i end
  end
  return worst, at
end

local function command(c, d, r)
  local cmd = c.teleop_cmd
  if not cmd then return end
  c.teleop_cmd = nil
  local cfg = config(c)
  if cmd.cmd == START then
    local rx = c.teleop_rx
    if r.state == 'running' or r.state == 'paused' then
      return answer(c, cmd, false, 'a trajectory is being played: stop it first')
    end
    if not (rx and rx.id == cmd.id) then
      local dropped = c.teleop_dropped
      if dropped and dropped.id == cmd.id then return answer(c, cmd, false, dropped.why) end
      return answer(c, cmd, false, string.format('trajectory %d has not arrived', cmd.id))
    end
    if not rx.whole then
      return answer(c, cmd, false, string.format('trajectory %d: %d of %d samples arrived', rx.id, rx.received, rx.n))
    end
    if not c.teleop_link_ok then return answer(c, cmd, false, 'the link is lost: nothing starts') end
    local e, j = off_start(c, rx)
    if e > cfg.start_tolerance then
      return answer(c, cmd, false, string.format('trajectory %d starts %.3f rad from the robot at %s (tolerance %.3f)',
        rx.id, e, c.robot.joints[j], cfg.start_tolerance))
    end
    d.traj, d.k, d.seg, d.finish_to, d.played = rx, 0, 1, nil, rx.id
    r.state, r.reason = 'running', ''
    return answer(c, cmd, true)
  elseif cmd.cmd == PAUSE then
    if r.state ~= 'running' then return answer(c, cmd, false, 'nothing is being played') end
    r.state = 'paused'
    return answer(c, cmd, true)
  elseif cmd.cmd == RESUME then
    if r.state ~= 'paused' then return answer(c, cmd, false, 'nothing is paused') end
    if not c.teleop_link_ok then return answer(c, cmd, false, 'the link is lost: nothing resumes') end
    r.state = 'running'
    return answer(c, cmd, true)
  elseif cmd.cmd == STOP then
    if d.traj then r.reason = string.format('stopped at sample %d', d.k) end
    d.traj = nil
    r.state = 'stopped'
    return answer(c, cmd, true)
  end
  return answer(c, cmd, false, 'unknown command ' .. tostring(cmd.cmd))
end

function M.update(c)
  local d = c:scratch('teleop')
  local r = d.report
  c.teleop_report = r
  -- a new trajectory arriving: the link reports it loading or ready
  local rx = c.teleop_rx
  if rx and rx.id ~= d.played and r.state ~= 'running' and r.state ~= 'paused' then r.state = 'idle' end
  command(c, d, r)
  local cfg = config(c)
  if r.state == 'running' then
    local traj = d.traj
    if not c.teleop_link_ok and not d.finish_to then
      if cfg.on_lost == 'hold' then
        r.state, r.reason = 'held', string.format('link lost: held at sample %d', d.k)
      else
        d.finish_to = traj.segments[math.max(d.seg, 1)]
      end
    end
    if r.state == 'running' then
      d.k = d.k + 1
      local q = traj.q[d.k]
      for i = 1, c.n do c.q[i] = q[i] end
      if d.k >= traj.segments[d.seg] and d.k < traj.n then d.seg = d.seg + 1 end
      if d.k >= traj.n then
        r.state, r.reason = 'done', ''
        d.traj = nil
      elseif d.finish_to and d.k >= d.finish_to then
        r.state, r.reason = 'held', string.format('link lost: segment finished at sample %d, held', d.k)
      end
    end
  end
  r.sample, r.segment = d.k, d.seg
  for i = 1, c.n do c.h[i] = cfg.hardness end
  if c.want ~= 'teleop' then
    if r.state == 'running' or r.state == 'paused' then
      r.reason = string.format('left for %s at sample %d', c.want, d.k)
    end
    return 'done'
  end
end

function M.exit(c)
  local d = c:scratch('teleop')
  d.traj = nil
  c.teleop_report = nil
  c.teleop_reason = d.report.reason ~= '' and d.report.reason or nil
end

return M
