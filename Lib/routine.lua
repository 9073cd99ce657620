-- Routines: a body's sequence of motions from config, played from the REPL or a script (the dance
-- of the HOAP-3). A routine, the concern routines/<name> (Config/robots/<body>/routines/<name>.lua,
-- checked by Config/spec/routines.lua): `steps`, each one of
--   { skill = name, seconds = s }    whole-body control running that skill (Motion.request('wbc', ...))
--   { walk = { vx, vy, va }, seconds = s }   walking at that velocity (m/s, m/s, rad/s)
--   { stand = true, seconds = s }    standing
-- played in order `rounds` times. Between steps of different kinds the robot passes through stance.
--
--   local routine = require('routine')
--   local report = routine.play('dance', wait, { each = function(step, k, round) end })
--   -- report: { seconds = robot s, steps = n, falls = n, stopped = why or nil }
-- wait: the REPL's wait(seconds) (lets the robot's clock run). M.kind(step): 'skill', 'walk' or
-- 'stand'. opts.rounds: play that many rounds
-- instead of the routine's (a short run of a long routine). opts.each(step, k, round) is called
-- every wait slice (default 0.05 s) while a step runs, e.g. to sample the robot; it may return a
-- string to stop the routine (the reason). A fall stops it too.
local Config = require('Config')
local Motion = require('Motion')
local Walk = require('Walk')
local Body = require('Body')

local M = {}

-- The routine `name` for the body (opts.robot, default ROBOT); errors name the file and key.
function M.load(name, opts)
  if type(name) ~= 'string' or not name:match('^[%w_]+$') then
    error("routine: the name must be a word, got '" .. tostring(name) .. "'", 2)
  end
  return Config.load('routines/' .. name, nil, { robot = opts and opts.robot })
end

-- Robot time until pred() holds (at most `timeout` s), waiting in `slice` s steps.
local function wait_for(wait, pred, timeout, slice)
  local t0 = Body.get_time()
  while not pred() and Body.get_time() - t0 < timeout do wait(slice) end
  return pred()
end

-- A step's kind: 'skill', 'walk' or 'stand' (the spec lets exactly one be there).
function M.kind(step)
  return Config.optional(step, 'skill') and 'skill' or Config.optional(step, 'walk') and 'walk' or 'stand'
end

local function start(step, wait, slice)
  local k = M.kind(step)
  if k == 'skill' then
    Motion.request('wbc', { skill = step.skill })
    return wait_for(wait, function() return Motion.state() == 'wbc' end, 5, slice)
  end
  if k == 'walk' then
    assert(Walk.set_velocity(step.walk[1], step.walk[2], step.walk[3]))
    Motion.request('walk')
    return wait_for(wait, function() return Motion.state() == 'walk' end, 5, slice)
  end
  Walk.stop()
  Motion.request('stand')
  return wait_for(wait, function() return Motion.state() == 'stance' end, 5, slice)
end

-- Plays routine `name`; returns the report (see the header).
function M.play(name, wait, opts)
  opts = opts or {}
  local r = M.load(name, opts)
  local slice = opts.slice or 0.05
  local t0, falls0, steps = Body.get_time(), Motion.falls(), 0
  local stopped
  for round = 1, opts.rounds or r.rounds do
    for k, step in ipairs(r.steps) do
      if not start(step, wait, slice) then
        stopped = string.format('step %d of round %d did not start (the motion is %s)', k, round, Motion.state())
      end
      local ts = Body.get_time()
      while not stopped and Body.get_time() - ts < step.seconds do
        wait(slice)
        if Motion.falls() > falls0 then stopped = 'the robot fell' end
        local why = opts.each and opts.each(step, k, round)
        if why then stopped = why end
      end
      steps = steps + 1
      if stopped then break end
    end
    if stopped then break end
  end
  -- standing at the end (the walk stopped first: a step of the walk ends on both feet)
  Walk.stop()
  Motion.request('stand')
  wait_for(wait, function() return Motion.state() == 'stance' end, 5, slice)
  return { seconds = Body.get_time() - t0, steps = steps, falls = Motion.falls() - falls0, stopped = stopped }
end

return M
