#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# history() (TAP): while the recorder runs over a stand-in robot (fake_robot.lua), the REPL's
# history('dcm.sensor.gyro', 1.0) returns the last second of samples, oldest first, each the value the
# robot wrote for its time; one element; a field that does not exist is an error naming it.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
source Tests/recorder/lib.sh
rec_fake 1.5
./run_repl -e "
local t, v = history('dcm.sensor.gyro', 1.0)
local ok, bad = true, 0
for i = 1, #t do
  local tick = math.floor(t[i] / 0.008 + 0.5)
  if v[i][3] ~= tick / 3 then bad = bad + 1 end
  if i > 1 and t[i] <= t[i - 1] then ok = false end
end
print(string.format('# %d samples from t=%.3f to t=%.3f, %d wrong', #t, t[1] or -1, t[#t] or -1, bad))
print(string.format('%s 1 - history returns the last second of samples, oldest first, with their values',
  (#t >= 40 and ok and bad == 0 and t[#t] - t[1] <= 1.0 and t[#t] - t[1] > 0.9) and 'ok' or 'not ok'))
local _, p = history('dcm.sensor.position', 0.5, 2)
print(string.format('%s 2 - one element of an array field', (type(p[1]) == 'number' and p[#p] % 1 ~= 0) and 'ok' or 'not ok'))
local okk, err = pcall(history, 'dcm.sensor.nothere', 1.0)
print(string.format('%s 3 - an unknown field is an error naming it # %s', (not okk and tostring(err):find('nothere')) and 'ok' or 'not ok', err))
"
echo "1..3"
