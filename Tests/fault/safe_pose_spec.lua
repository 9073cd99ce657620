-- luacheck: std +busted
-- Each body's safe pose (robot.lua `safe_pose`: where the DCM's safe state moves the joints when
-- motion dies or stops answering, Modules/dcm/guard.c) names only the body's joints, within their
-- limits, with a ramp of a positive time. A misspelt joint would be held where it was unseen.
local Config = require('Config')

describe('safe_pose of every body', function()
  local p = io.popen('ls "' .. os.getenv('HRP_ROOT') .. '/Config/robots"')
  for robot in p:lines() do
    it(robot, function()
      local cfg = Config.export('robot', { robot = robot })
      local sp = cfg.safe_pose
      if sp == nil then return end
      assert.is_table(sp, robot .. ': safe_pose must be a table')
      assert.is_true(type(sp.ramp) == 'number' and sp.ramp > 0 and sp.ramp <= 1, robot .. ': safe_pose.ramp (s)')
      assert.is_true(sp.hardness == nil or (type(sp.hardness) == 'number' and sp.hardness >= 0 and sp.hardness <= 1),
        robot .. ': safe_pose.hardness within 0..1')
      local index = {}
      for i, j in ipairs(cfg.joints) do index[j] = i end
      for joint, angle in pairs(sp.q) do
        assert.is_not_nil(index[joint], robot .. ": safe_pose.q names '" .. tostring(joint) .. "', not a joint")
        local lim = cfg.limits[joint]
        assert.is_true(angle >= lim[1] and angle <= lim[2], robot .. ': safe_pose.q.' .. joint .. ' outside its limits')
      end
    end)
  end
  p:close()
end)
