-- The Hubo2+'s sizes and speeds for the behavior (Player/BodyFSM, HeadFSM), overlaid on
-- Config/common/behavior.lua (timing, game and field numbers, and a kid-size body's defaults).
-- Nothing asks the Hubo to play football: the defaults and the OP3's speeds, with the numbers that
-- depend on the body changed so that the behavior process runs on it: the torso origin 0.69 m up
-- when walking, the camera 0.52 m above it, a head that tilts +-30 deg and does not pan (its scan is
-- the waist's business: not done), the walk's speeds (Config/robots/hubo2plus/walk.lua). Units: m, s, rad.
return {
  head = {
    scan_pan = 0.4,            -- rad, half-range of the scan (the head pan's reach)
    ground_z = -0.69,          -- m: the ground below the torso origin (torso frame), for look-at
    camera_z = 0.52,           -- m, the camera above the torso origin (look-at without a kinematic model)
  },

  body = {
    approach_speed = 0.25,     -- m/s
    kick_x = 0.30,             -- m: ball this far ahead of the torso when kicking
    kick_y = 0.06,             -- m: ball this far to the side (towards the kicking foot)
    dribble = {
      speed = 0.25,            -- m/s forward
    },
    max_va = 0.5,              -- rad/s
  },
}
