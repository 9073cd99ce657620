-- luacheck: std +busted
-- ./run_repl: -e and file modes, exit status, wait() in lockstep.
local native = require('native')
local root = native.root()

local function run(cmd)
  local h = io.popen('cd ' .. root .. ' && ' .. cmd .. ' 2>&1; echo "rc=$?"')
  local out = h:read('*a')
  h:close()
  return out:gsub('rc=%d+%s*$', ''), tonumber(out:match('rc=(%d+)%s*$'))
end

describe('run_repl', function()
  it('runs -e CODE with Body, Config and the blocks bound', function()
    local out, rc = run([[./run_repl -e 'print(#Body.joint_names(), Config.platform(), type(dcm_sensor.position))']])
    assert.equal(0, rc, out)
    assert.truthy(out:find('20\tSim\tcdata', 1, true), out)
  end)

  it('exits non-zero with the message on a Lua error', function()
    local out, rc = run([[./run_repl -e 'error("boom here")']])
    assert.equal(1, rc)
    assert.truthy(out:find('boom here', 1, true))
    out, rc = run([[./run_repl -e 'this is not lua']])
    assert.equal(1, rc)
    assert.truthy(out:find('(-e)', 1, true), out)
  end)

  it('runs a script file with its arguments', function()
    local path = os.tmpname()
    local f = io.open(path, 'w')
    f:write('print("args", arg[1], arg[2]); print(Body.index("r_el"))\n')
    f:close()
    local out, rc = run('./run_repl ' .. path .. ' a b')
    os.remove(path)
    assert.equal(0, rc, out)
    assert.truthy(out:find('args\ta\tb', 1, true), out)
    assert.truthy(out:find('20', 1, true))
  end)

  it('wait() says so when no DCM is running', function()
    local out, rc = run([[ROBOT_ID=$((ROBOT_ID + 60000)) ./run_repl -e 'wait(0.1)']])
    assert.equal(1, rc)
    assert.truthy(out:find('is ./run_dcm running', 1, true), out)
  end)

  it('in lockstep, a script\'s commands land on the ticks its wait() calls reach', function()
    local log = os.tmpname()
    local dcm = io.popen('cd ' .. root .. ' && luajit Tests/foundation/fake_lockstep_dcm.lua 40 ' .. log .. ' 2>&1')
    local out, rc = run([[./run_repl -e 'Body.set_command(1, 0.25); wait(0.08); Body.set_command(1, 0.5);
      wait(0.08); Body.set_command(1, 1.0); wait(0.04)']])
    dcm:close()
    assert.equal(0, rc, out)
    local at = {}
    for line in io.lines(log) do
      local tick, cmd = line:match('(%d+) (%S+)')
      at[tonumber(tick)] = tonumber(cmd)
    end
    os.remove(log)
    -- the DCM steps tick 0 and waits for the new participant at tick 1
    assert.equal(0.25, at[1])
    assert.equal(0.25, at[10])
    assert.equal(0.5, at[11])
    assert.equal(0.5, at[20])
    assert.equal(1.0, at[21])
    assert.equal(1.0, at[39])
  end)
end)
