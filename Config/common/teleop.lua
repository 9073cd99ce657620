-- Teleoperation (docs/teleoperation.md): key poses (Config/robots/<body>/keyposes/<name>.lua,
-- checked by Config/spec/keyposes.lua) solved by the whole-body controller, the trajectories
-- between them checked before anything moves (Lib/teleop.lua), and the executor that plays a
-- checked trajectory (the motion state teleop, Player/Motion/states/teleop.lua).
return {
  -- a key pose's limbs: the frame each one's target is for (stance frame), and the link whose
  -- URDF collision boxes named sole* make a foot's part of the support polygon
  limbs = {
    lhand = { frame = 'l_palm' },
    rhand = { frame = 'r_palm' },
    pelvis = { frame = 'pelvis' },
    lfoot = { frame = 'l_sole', link = 'l_foot' },
    rfoot = { frame = 'r_sole', link = 'r_foot' },
  },
  -- the solve: the key pose's targets are reached by the whole-body controller stepping at the control
  -- period; the targets move from where the limbs are to the key pose's in the segment's first
  -- `share` of its duration (minimum jerk), the rest lets the controller settle on them
  solve = {
    share = 0.8,
    -- a free hand's and the pelvis's tasks: level under the balance (the wbc config's com task at 1),
    -- 1/s, m/s (the fastest a target may ask for; the controller's joint speed limits come on top)
    hand = { level = 2, gain = 8, max_rate = 0.6 },
    pelvis = { level = 2, gain = 8, max_rate = 0.3 },
    -- a held limb keeps its place as firmly as a free one is driven
    hold = { level = 2, gain = 8, max_rate = 0.6 },
    -- the centre of mass: over the stance frame's origin unless the key pose moves it (`com`)
    com = { level = 1, gain = 6, max_rate = 0.1 },
  },
  -- the checks along the whole trajectory (one sample per control period)
  check = {
    -- m: a free limb's distance from its target at the segment's end; over it: out of reach
    reach = 0.01,
    -- rad: a joint closer than this to its limit counts as beyond it (the servos' overshoot)
    limit_margin = 0.0,
    -- share of each actuator's no-load speed (Config/common/actuators.lua) a joint may use: the
    -- rest is the position loop's headroom to follow the trajectory at all
    speed_share = 0.8,
    -- m: two collision shapes closer than this collide (the shapes are the URDF's boxes)
    collision_margin = 0.005,
    -- links this many joints apart or fewer are not checked against each other: a hip's three axes
    -- (and a shoulder's) meet at one point, and the boxes around them overlap at any angle
    collision_skip_joints = 3,
    -- m: the centre of mass stays this far inside the support polygon (the convex hull of the
    -- soles); 0.02 m is 10 % of the Hubo2+'s 0.22 m foot, a margin the DRC-HUBO's static checks used
    -- in spirit (the ZMP of a slow motion sits next to the centre of mass)
    com_margin = 0.02,
    -- m: a held foot may drift this far in the solved trajectory before it is refused (it would
    -- slide on the ground)
    foot_drift = 0.005,
  },
  -- the executor
  executor = {
    -- s without a new operator heartbeat: the link is lost
    link_timeout = 0.5,
    -- on a lost link: 'finish' the segment being played then hold, or 'hold' at once; never the next
    on_lost = 'finish',
    -- rad: the robot's joints must be this close to a trajectory's first sample for it to start
    start_tolerance = 0.05,
    -- the hardness the joints are driven at
    hardness = 1.0,
  },
}
