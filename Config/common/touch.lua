-- The touch motion (Motion.request('touch'): Player/Motion/states/touch.lua): arms move from where
-- they are towards a pose, each stopping where the force at its hand first exceeds `force`, then
-- holding there, pressing no harder than the servo's lag at that moment. A body lists its arms in its
-- own touch.lua; one that lists none cannot touch (the request is refused).
return {
  -- Each: { sensor = 'lhand' | 'rhand' (robot.lua ft: the wrist sensor whose force stops the arm),
  --         to = { joint = rad, ... } (the pose the arm moves towards; its joints are the motion's) }
  arms = {},
  speed = 0.3,      -- rad/s: the arm's joint that has the farthest to go moves this fast
  force = 1.0,      -- N: the force at the wrist that means touching (well above the hand's weight)
  -- N: once touching, the arm presses this hard along its path: it moves on while the force is below
  -- and back while above, at most at half its sweep speed (a gentle, steady contact that a sway of
  -- the body does not break)
  press = 2.0,
  -- s the force must stay above `force` before the arm stops: one tick's jolt (the arm starting to
  -- move, an elbow knocking the body) is not a touch
  confirm = 0.02,
}
