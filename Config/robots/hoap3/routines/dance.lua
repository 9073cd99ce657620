-- The HOAP-3's 3-minute dance (Lib/routine.lua; the HOAP-3 study's dance): its standing moves (the
-- whole-body skill wbc_skills/dance.lua: weight shifts, arms, a squat, waves, a bow; 28 s), then a
-- quarter turn on the spot (the walk at 0.2 rad/s for 7.5 s), five times round: facing each way once
-- and the first way again.
return {
  rounds = 5,
  steps = {
    { skill = 'dance', seconds = 28 },
    { walk = { 0, 0, 0.2 }, seconds = 7.5 },
    -- standing still a moment: the walk's last sway dies out before the next moves start
    { stand = true, seconds = 1.5 },
  },
}
