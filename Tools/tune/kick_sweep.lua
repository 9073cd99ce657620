-- Kicks over ball placements in one sim (lockstep), one line of figures per kick (kick_measure.lua):
--   ./run_repl Tools/tune/kick_sweep.lua SIDES GAPS LATERALS
-- SIDES: 'left,right'; GAPS: m from the toe to the ball's centre ('0.08,0.1,0.12'); LATERALS: m of
-- the ball's centre outward of the sole's centre ('-0.02,0,0.02'). Ends with a line
-- "sweep n=N min=D mean=D fallen=F".
-- luacheck: globals Sim Motion wait arg Body
if not Sim then
  package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
  Sim = require('sim_shim')
end
-- kick_measure beside this file; kick_setup and sim_shim with the scenarios they serve (Tests/motion)
local root = os.getenv('HRP_ROOT')
package.path = root .. '/Tools/tune/?.lua;' .. root .. '/Tests/motion/?.lua;' .. package.path
local km = require('kick_measure')

local function list(s, default)
  local t = {}
  for x in (s or default):gmatch('[^,]+') do t[#t + 1] = tonumber(x) or x end
  return t
end
local sides, gaps, lats = list(arg[1], 'left,right'), list(arg[2], '0.1'), list(arg[3], '0')

assert(require('kick_setup').wait_for_motion(wait), 'the motion process is not running')

km.apply_env(wait)   -- KICK_PARAMS=file.lua: a tuned set (kick_tune.lua) instead of the config's
local env = { Sim = Sim, Motion = Motion, wait = wait, Body = Body }
local worst, sum, fallen, n = math.huge, 0, 0, 0
for _, side in ipairs(sides) do
  for _, gap in ipairs(gaps) do
    for _, lat in ipairs(lats) do
      local f = km.kick(env, side, gap, lat)
      print('# ' .. km.describe(side, gap, lat, f))
      io.stdout:flush()
      n = n + 1
      if f.bad then fallen = fallen + 1 end
      worst, sum = math.min(worst, f.d), sum + f.d
    end
  end
end
print(string.format('sweep n=%d min=%.3f mean=%.3f fallen=%d', n, worst, sum / n, fallen))
