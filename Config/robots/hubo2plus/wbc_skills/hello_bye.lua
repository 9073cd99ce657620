-- The Hubo2+ waves (stanford-wbc's "hello-bye" as a skill, Lib/wbc_skill.lua; docs/whole-body.md):
-- the right palm up beside the head, over to either side of it three times, then down again (its
-- task dropped: the wbc config's posture, faster, takes the arm back to where the skill started). Targets
-- in the stance frame (m): on the ground midway between the soles, x ahead, y left, z up; the
-- shoulder is about 1.0 m up and 0.21 m right, the palm 0.42 m from it with the arm straight, so
-- every target sits 0.25-0.32 m from the shoulder (the elbow bent). Levels and gains as the wbc
-- config's `reach` (a palm task the REPL made keeps them: a task keeps its kind and max_rate).
local function palm(y) return { kind = 'position', frame = 'r_palm', level = 2, gain = 3, max_rate = 0.15,
  target = { 0.20, y, 1.15 } } end

return {
  initial = 'hello',
  states = {
    -- up beside the head; on within 1 cm (the model's error), or after 5 s wherever it got to
    hello = { tasks = { r_palm = palm(-0.32) }, next = { go = 'wave_out', reached = { r_palm = 0.01 }, after = 5 } },
    -- out to the side and back in, three times (the rule with `times` first, then the way down)
    wave_out = { tasks = { r_palm = palm(-0.42) }, next = { go = 'wave_in', reached = { r_palm = 0.01 }, after = 3 } },
    wave_in = { tasks = { r_palm = palm(-0.26) }, next = {
      { go = 'wave_out', reached = { r_palm = 0.01 }, after = 3, times = 2 },
      { go = 'bye', reached = { r_palm = 0.01 }, after = 3 },
    } },
    -- the palm's task dropped: the posture brings the arm back, at three times its gain in the wbc config
    -- (its max_rate, 0.5 rad/s, bounds it: the shoulder comes down 1.4 rad in about 3 s); the skill rests here
    bye = { tasks = { posture = { kind = 'posture', level = 4, gain = 3, max_rate = 0.5, target = 'entry' } } },
  },
}
