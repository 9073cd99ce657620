-- The OP3's head camera (Logitech C920): vertical field of view.
return {
  fovy = math.rad(43.3),        -- rad
}
