-- The venue's colour table (the site layer). Train one for the field (Tools/lut: capture frames,
-- label them, `lut_tool train`) and name it here; false: the table is built from the colour boxes of
-- Config/common/vision.lua, which fit only the sim's renderer.
return {
  lut = false,
}
