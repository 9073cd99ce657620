-- Under Sim the camera frames come from the sim DCM (Config/platforms/Sim/sim.lua's camera section
-- renders them into camera.image).
return {
  driver = 'sim',
}
