-- The walking-vision figures of several runs (walk_eye.lua with WALK_EYE_SAVE) together, and TAP.
--   luajit Tests/vision/walk_merge.lua GATE MIN_INVIEW FILE...
-- GATE: the goals to fail on (recall,false,range,bearing; the others print); MIN_INVIEW: the
-- frames with the ball fully in view needed.
local stats = require('Tests.vision.walk_stats')
local gate, min_inview = arg[1], tonumber(arg[2])
local files = {}
for i = 3, #arg do files[#files + 1] = arg[i] end
if not min_inview or #files == 0 then
  io.stderr:write('usage: walk_merge.lua GATE MIN_INVIEW FILE...\n')
  os.exit(2)
end
local all = stats.merge(files)
print(string.format('# all %d runs together; frames not scored: %s', #files, all:skipped()))
all:report()
all:tap(gate, { min_inview = min_inview })
