-- The test body's head camera: the OP3's (Config/robots/op3/camera.lua); the head's joints sit
-- elsewhere in this body's joint order.
local fovy = math.rad(43.3)
local f = 240 / math.tan(fovy / 2)
return {
  fovy = fovy,                  -- rad
  intrinsics = { fx = f, fy = f, cx = 319.5, cy = 239.5 },
  distortion = { k1 = 0.10, k2 = -0.25 },
  head_joint = { 20, 21 },      -- 0-based indices of head_pan, head_tilt in the joint order
}
