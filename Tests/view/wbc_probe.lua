-- For Tests/view/view_test.sh: the robot (motion alone, real time) into the whole-body state, the
-- centre of mass given a target 1 cm to the left; prints the state and the tasks.
-- luacheck: globals Motion WBC wait
Motion.request('stand')
wait(2)
Motion.request('wbc')
wait(1)
WBC.set_target('com', { 0, 0.01 })
wait(0.5)
local s = WBC.status()
local names = {}
for name, t in pairs(s.tasks) do
  names[#names + 1] = string.format('%s (level %d, error %.4f)', name, t.level, t.error)
end
table.sort(names)
print(string.format('motion state %s, wbc active %s: %s', Motion.state(), tostring(s.active),
  table.concat(names, ', ')))
assert(Motion.state() == 'wbc' and s.active, 'the wbc state does not run')
