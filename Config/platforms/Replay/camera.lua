-- Under Replay the camera frames come from the log: the Replay DCM writes them into camera.image as the
-- sim DCM does, so the vision process reads them through the same driver.
return {
  driver = 'sim',
}
