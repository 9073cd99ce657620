-- Vision on the real robots: the simulated robot's detector settings (Config/Sim/vision.lua) with a
-- colour table trained on the venue's field. The sim's colour boxes only fit the sim's renderer:
-- capture frames (`Run/lut_tool/lut_tool frame --shm`), label them, train a table (`lut_tool train
-- --colors ...`) and name it in `lut` below, or set the environment variable HRP_LUT to its path.
local here = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or 'Config/OP'
local vision = dofile(here .. '/../Sim/vision.lua')
vision.lut = os.getenv('HRP_LUT') or false
return vision
