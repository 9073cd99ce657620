-- The HOAP-3's dance moves (a whole-body skill, Lib/wbc_skill.lua; docs/whole-body.md), the part of
-- its dance routine (routines/dance.lua) done standing on both feet: weight shifts from foot to foot,
-- the arms opened, a squat, waves of one arm and the other, a bow of the trunk. Targets in the stance
-- frame (m): on the ground midway between the soles, x ahead, y left, z up. Standing, the soles'
-- centres are 0.039 m either side, the pelvis (WAIST) 0.240 m up and pitched 0.15 rad forward (the
-- walk's stance), the shoulders about 0.40 m up and 0.111 m out, each arm 0.214 m long to its hand
-- frame (hanging: 0.02 m ahead, 0.13 m out, 0.21 m up; the elbow bends at most 115 degrees: a hand
-- comes no closer than 0.10 m to its shoulder). The pelvis and the trunk keep their standing
-- orientation in every state (the bow pitches the trunk): without them the controller tips the whole
-- body back to reach with the arms. The balance task (com) keeps its level, gain and rate.
local function com(y) return { kind = 'com_xy', level = 1, gain = 4, max_rate = 0.05, target = { 0, y } } end
local function hand(frame, x, y, z)
  return { kind = 'position', frame = frame, level = 3, gain = 3, max_rate = 0.15, target = { x, y, z } }
end
-- frame pitched forward by `a` rad about the stance frame's y axis
local function pitched(frame, a, max_rate)
  local c, s = math.cos(a), math.sin(a)
  return { kind = 'orientation', frame = frame, level = 2, gain = 2, max_rate = max_rate,
    target = { c, 0, s, 0, 1, 0, -s, 0, c } }
end
local function pelvis_height(z) return { kind = 'position', frame = 'WAIST', level = 2, gain = 2, max_rate = 0.03,
  target = { -0.003, 0, z } } end
local STANDING = 0.15

-- a state's tasks: the balance, the pelvis and trunk orientations, and `more`
local function with(y, trunk, more)
  local t = { com = com(y), hips = pitched('WAIST', STANDING, 0.3), trunk = pitched('CHEST', trunk or STANDING, 0.3) }
  for k, v in pairs(more or {}) do t[k] = v end
  return t
end
-- both arms out to the sides a little below shoulder height
local OPEN = { l_hand = hand('l_hand', 0.04, 0.24, 0.34), r_hand = hand('r_hand', 0.04, -0.24, 0.34) }
local function open_and(more)
  local t = { l_hand = OPEN.l_hand, r_hand = OPEN.r_hand }
  for k, v in pairs(more or {}) do t[k] = v end
  return t
end
-- one arm raised forward and up, the other low in front
local function wave(up, down)
  local side = up == 'l_hand' and 1 or -1
  return { [up] = hand(up, 0.15, 0.13 * side, 0.48), [down] = hand(down, 0.08, -0.13 * side, 0.24) }
end

return {
  initial = 'left',
  states = {
    -- the weight over the left sole, the right, twice (2.5 cm: inside both soles' polygon)
    left = { tasks = with(0.025), next = { go = 'right', after = 2.0 } },
    right = { tasks = with(-0.025), next = { { go = 'left', after = 2.0, times = 1 }, { go = 'open', after = 2.0 } } },
    open = { tasks = with(0, nil, open_and()), next = { go = 'squat', after = 2.5 } },
    -- down 2.5 cm and up again, arms open
    squat = { tasks = with(0, nil, open_and({ pelvis = pelvis_height(0.215) })), next = { go = 'rise', after = 2.5 } },
    rise = { tasks = with(0, nil, open_and({ pelvis = pelvis_height(0.240) })), next = { go = 'wave_l', after = 2.0 } },
    -- one arm up and the other low, then the other way, three times
    wave_l = { tasks = with(0, nil, wave('l_hand', 'r_hand')), next = { go = 'wave_r', after = 1.5 } },
    wave_r = { tasks = with(0, nil, wave('r_hand', 'l_hand')),
      next = { { go = 'wave_l', after = 1.5, times = 2 }, { go = 'bow', after = 1.5 } } },
    -- the trunk bowed 0.25 rad further forward (the arms back to where the skill started: the posture)
    bow = { tasks = with(0, STANDING + 0.25), next = { go = 'done', after = 3.0 } },
    -- upright again; the skill rests here
    done = { tasks = with(0) },
  },
}
