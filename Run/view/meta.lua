-- What the live view needs to know about the robot beside its shm blocks, as one JSON document on
-- stdout: the configuration in force (robot, vision, behavior, camera concerns, as the recorder
-- attaches them) and the names behind the state indices of the motion, vision and game blocks.
--   luajit Run/view/meta.lua LUT_PATH     also writes the vision's colour table (lookup table) to LUT_PATH
local config_dump = require('Run.config_dump')
local Config = require('Config')
local pipeline = require('Vision.pipeline')
local imageproc = require('imageproc')

local function names(list)
  local q = {}
  for i, s in ipairs(list) do q[i] = string.format('%q', s) end
  return '[' .. table.concat(q, ',') .. ']'
end

local lut_path = ...
if lut_path then
  local lut = assert(pipeline.load_lut(Config.load('vision')))
  assert(imageproc.save_lut(lut_path, lut))
end

local parts = {}
for _, doc in ipairs(config_dump({ 'robot', 'vision', 'behavior', 'camera', 'sim' })) do
  parts[#parts + 1] = string.format('%q:%s', doc.name, doc.json)
end
local states = {
  string.format('"motion":%s', names(require('Motion').STATES)),
  string.format('"body":%s', names(require('BodyFSM.machine').states)),
  string.format('"head":%s', names(require('HeadFSM.machine').states)),
  string.format('"role":%s', names(require('Team.roles').ROLES)),
  '"game":["initial","ready","set","playing","finished"]',
}
io.write('{"config":{', table.concat(parts, ','), '},"states":{', table.concat(states, ','), '}}\n')
