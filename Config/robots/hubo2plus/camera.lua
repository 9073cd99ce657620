-- The Hubo2+'s head camera: no public data on it (shared/robots/hubo_reference.txt has no CAMERA),
-- and nothing of the Hubo needs vision yet; the vision process reads this file, so: a webcam's
-- field of view (the OP3's C920, chosen), a plain pinhole, and the head's joints in this body's
-- joint order.
local fovy = math.rad(43.3)
local f = 240 / math.tan(fovy / 2)
return {
  fovy = fovy,                  -- rad
  intrinsics = { fx = f, fy = f, cx = 319.5, cy = 239.5 },
  distortion = { k1 = 0, k2 = 0 },
  head_joint = { 1, 2 },        -- 0-based indices of NK1, NK2 in the joint order (robot.lua)
}
