-- Kicks out of the walk over a sweep of ball positions, run by ./run_repl in the sim's lockstep
-- with the motion process alone (Tests/motion/walk_kick_sweep.sh):
--   ./run_repl Tests/motion/walk_kick_scenario.lua [SWEEPS] [FEET] [VX]
-- SWEEPS 'forward=XS/YS;side=XS/YS' with XS, YS lists ('-0.03,0.03'): the ball's centre from the kick
-- zone's nominal spot (m, ahead and outward: the walk config's walkKick.<kind>.ball); FEET
-- 'left,right'; VX: the walk's forward speed (m/s). For each case the robot walks, the ball is put in front of
-- it, the kick is asked for through Walk.kick (with the ball's position in the robot frame, as
-- the behavior gives it) and the robot walks on; the ball's travel is measured from the sim's
-- truth once it stops. Prints one line per case and TAP lines: every kick sends the ball
-- >= MIN m (env WALK_KICK_MIN_<KIND>, defaults forward 1.5, the goal; side 0.4: what the
-- OP3's side kick does; the 1.5 m goal is printed against the shortest forward kick),
-- the walk's step counter kept going, no fall.
-- WALK_KICK_TRACE=FILE: the kicking foot's toe, the ball and the torso every tick (for plotting:
-- Tools/plot/plot_walk_kick.py).
-- luacheck: globals Sim Motion Walk wait arg Body
package.path = os.getenv('HRP_ROOT') .. '/Tests/motion/?.lua;' .. package.path
local ks = require('kick_setup')
local Config = require('Config')
local sc = require('Tests.scenario_lib').new(wait, Body)
local tap, note = sc.tap, sc.note

local function list(s, default)
  local t = {}
  for x in (s or default):gmatch('[^,]+') do t[#t + 1] = tonumber(x) or x end
  return t
end
local sweeps = {}
for kind, xs, ys in (arg[1] or 'forward=0/0;side=0/0'):gmatch('(%a+)=([^/;]+)/([^;]+)') do
  sweeps[#sweeps + 1] = { kind = kind, xs = list(xs), ys = list(ys) }
end
local feet = list(arg[2], 'left,right')
local vx = tonumber(arg[3] or '0.12')
local need = { forward = tonumber(os.getenv('WALK_KICK_MIN_FORWARD') or '1.5'),
  side = tonumber(os.getenv('WALK_KICK_MIN_SIDE') or '0.4') }
local GOAL = 1.5 -- m, the goal for a kick out of the walk
local p = Config.load('walk')
local motion = assert(ks.wait_for_motion(wait), 'the motion process is not running')
local trace = os.getenv('WALK_KICK_TRACE') and assert(io.open(os.getenv('WALK_KICK_TRACE'), 'w'))
if trace then trace:write('# case t toe_x toe_y toe_z ball_x ball_y ball_z torso_x torso_y phase\n') end

-- the ball's centre in the robot frame (x ahead of the torso, y left) for a case
local function ball_spot(kind, foot, dx, dy)
  local b = p.walkKick[kind].ball
  local sgn = foot == 'left' and 1 or -1
  -- the support ankle is about footY to the other side of the torso
  return b.x + dx, sgn * (p.footY + b.y + dy)
end

local results, ncase = {}, 0
for _, sw in ipairs(sweeps) do
  local kind = sw.kind
  for _, foot in ipairs(feet) do
    for _, dx in ipairs(sw.xs) do
      for _, dy in ipairs(sw.ys) do
        ncase = ncase + 1
        ks.walk_steady(Sim, Motion, Walk, wait, vx)
        local falls0, steps0 = Motion.falls(), motion.walk_steps[0]
        local _, kicks0 = Walk.kick_status()
        local r = Sim.truth()
        local bx, by = ball_spot(kind, foot, dx, dy)
        local c, s = math.cos(r.yaw), math.sin(r.yaw)
        Sim.teleport_ball(r.x + c * bx - s * by, r.y + s * bx + c * by)
        wait(0.01)
        local b0 = Sim.truth().ball
        Walk.kick(kind, foot, bx, by)
        local t0, kicked, tstop = Body.get_time(), nil, nil
        local prev = Sim.truth()
        -- walk on until the ball has come to rest (or 8 s)
        while Body.get_time() - t0 < 8 do
          wait(0.008)
          r = Sim.truth()
          local phase, kicks = Walk.kick_status()
          if kicks > kicks0 and not kicked then kicked = Body.get_time() - t0 end
          if trace and Body.get_time() - t0 < 3.0 then -- a kick may wait up to walkKick.expire (2 s)
            local toe = ks.to_world(r, ks.toe_in_torso(foot, ks.leg(foot)))
            trace:write(string.format('%d %.3f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %s\n', ncase,
              Body.get_time() - t0, toe[1], toe[2], toe[3], r.ball.x, r.ball.y, r.ball.z, r.x, r.y, phase))
          end
          local moved = math.sqrt((r.ball.x - b0.x) ^ 2 + (r.ball.y - b0.y) ^ 2)
          local speed = math.sqrt(r.ball.vx ^ 2 + r.ball.vy ^ 2)
          if kicked and moved > 0.05 and speed < 0.02 then tstop = Body.get_time() - t0 break end
          prev = r
        end
        r = prev
        local d = math.sqrt((r.ball.x - b0.x) ^ 2 + (r.ball.y - b0.y) ^ 2)
        -- the walk goes on: 3 s past the kick, the steps counted from the request
        while Body.get_time() - t0 < (kicked or 0) + 3 do wait(0.05) end
        -- the ball's direction against the robot's heading (forward 0, left +)
        local dir = math.atan2(r.ball.y - b0.y, r.ball.x - b0.x) - r.yaw
        dir = (dir + math.pi) % (2 * math.pi) - math.pi
        local steps = motion.walk_steps[0] - steps0
        local fell = Motion.falls() > falls0 or r.fallen
        local fell_at = fell and motion.fall_time[0] - t0 or nil
        local walking = motion.walking[0] == 1 and Motion.state() == 'walk'
        results[#results + 1] = { kind = kind, foot = foot, d = d, fell = fell, steps = steps, walking = walking }
        note('%-7s %-5s ball (%.3f, %+.3f) m: %.2f m at %+4.0f deg, kick at %s s, ball still at %s s, %d steps, %s%s',
          kind, foot, bx, by, d, math.deg(dir), kicked and string.format('%.2f', kicked) or 'never',
          tstop and string.format('%.1f', tstop) or '-', steps, walking and 'walking' or 'NOT walking',
          fell and string.format(', FELL at %.1f s', fell_at) or '')
      end
    end
  end
end
if trace then trace:close() end

local worst, fell, stopped = math.huge, 0, 0
local short, least = 0, {} -- kicks under their kind's minimum; the shortest per kind
for _, k in ipairs(results) do
  worst = math.min(worst, k.d)
  least[k.kind] = math.min(least[k.kind] or math.huge, k.d)
  if k.d < need[k.kind] then short = short + 1 end
  if k.fell then fell = fell + 1 end
  if not k.walking or k.steps < 10 then stopped = stopped + 1 end
end
if least.forward then
  note('forward kicks: shortest %.2f m (goal %.1f m: %s)', least.forward, GOAL,
    least.forward >= GOAL and 'met' or 'NOT met')
end
note('walk kicks: %d, shortest %.2f m, falls %d, walk stopped %d', #results, worst, fell, stopped)
local per = {}
for _, kind in ipairs({ 'forward', 'side' }) do
  if least[kind] then per[#per + 1] = string.format('%s >= %.1f m: shortest %.2f m', kind, need[kind], least[kind]) end
end
tap(short == 0, string.format('every walk kick sends the ball its minimum (%s; %d short of %d)',
  table.concat(per, ', '), short, #results))
tap(fell == 0 and stopped == 0, string.format('the robot walks on through every kick (falls %d, stopped %d)', fell,
  stopped))
