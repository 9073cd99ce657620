-- The test body's head camera: the OP3's (Config/robots/op3/camera.lua); the head's joints sit
-- elsewhere in this body's joint order.
return {
  fovy = math.rad(43.3),        -- rad
  head_joint = { 20, 21 },      -- 0-based indices of head_pan, head_tilt in the joint order
}
