-- Defaults for every body's robot.lua (Config/robots/<ROBOT>/robot.lua holds the body: its joints,
-- groups, limits, actuators, frames and buses). Lists are replaced whole, tables merged key by key
-- (Lib/Config.lua), so only what every body shares or may leave out is here.
return {
  -- the DCM's control period, s (125 Hz: the Dynamixel bodies' bus cycle)
  period = 0.008,
  -- the kinematics' named chains (Lib/kinematics.lua): joints from the base to the tip (default:
  -- the group of the same name) and the tip, a frame of the body's URDF (Tools/urdf/gen_urdf.py adds the
  -- frames a body's `frames` names)
  chains = {
    lleg = { tip = 'l_sole' }, rleg = { tip = 'r_sole' },
    larm = { tip = 'l_hand' }, rarm = { tip = 'r_hand' },
    head = { tip = 'camera_link' },
  },
}
