-- luacheck: std +busted
-- The motion state wbc (Player/Motion/states/wbc.lua) and its shm link (Player/Motion/wbc_link.lua)
-- without a robot: the Hubo2+'s joints follow the commands perfectly. The garbage one tick makes
-- (collectgarbage('count') over N ticks with the collector stopped, printed), the status block
-- left alone while the state does not run, the skill hello_bye run through its states, and skill
-- files naming what the body lacks refused with the file and the key.
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local wbc_link = require('Motion.wbc_link')
local wbc_skill = require('wbc_skill')
local wbc = require('wbc')
local shm = require('shm')
local ffi = require('ffi')

local BODY = 'hubo2plus'
local robot = Config.load('robot', nil, { robot = BODY })
local params = Config.load('walk', nil, { robot = BODY })
local model = kin.load({ robot = BODY })
local N = 2000

local function tick(c, link, k)
  for i = 1, c.n do c.pos[i] = c.q[i] end
  link:before(c)
  c:tick(c.t + c.dt)
  link:after(c, k)
end

local function block_of(link) return link.b end

-- bytes of garbage per tick over n ticks
local function garbage(c, link, n)
  collectgarbage('collect')
  collectgarbage('stop')
  local k0 = collectgarbage('count')
  for k = 1, n do tick(c, link, k) end
  local per = (collectgarbage('count') - k0) * 1024 / n
  collectgarbage('restart')
  return per
end

describe('the wbc motion state', function()
  local block = shm.open('wbc')
  local link = wbc_link.new(block)
  local c = control.new({ robot = robot, params = params, model = model })

  it('leaves the status block alone while it does not run', function()
    for k = 1, 400 do tick(c, link, k) end
    assert.equals('stance', c:state())
    block:write(function(x) x.tick[0] = 12345 end)
    local stance = garbage(c, link, N)
    assert.equals(12345, block.tick[0])
    print(string.format('# stance (wbc not running): %.1f bytes of garbage per tick (%d ticks)', stance, N))
  end)

  it("numbers the task kinds in the block as the controller's C API does", function()
    for name, k in pairs(wbc.KINDS) do assert.equals(tonumber(k), wbc_link.KIND[name], name) end
  end)

  it('makes no garbage per tick while it runs', function()
    c:request('wbc')
    for k = 1, 200 do tick(c, link, k) end
    assert.equals('wbc', c:state())
    assert.equals(1, block.active[0])
    local per = garbage(c, link, N)
    print(string.format('# wbc state + status block: %.1f bytes of garbage per tick (%d ticks)', per, N))
    assert.equals(N, block.tick[0])
    assert.is_true(per < 16, string.format('%.1f bytes per tick', per))
  end)
end)

-- A config root beside the project's with extra skill files for the Hubo2+ (name -> text): every
-- folder a link to the project's, the body's folder a folder of links plus wbc_skills/.
local function fake_root(files)
  local real = Config.robot_dir(BODY):gsub('/Config/robots/' .. BODY .. '$', '')
  local dir = os.tmpname()
  os.remove(dir)
  local function sh(cmd) assert(os.execute(cmd) == 0, cmd) end
  sh(string.format("mkdir -p '%s/Config/robots/%s/wbc_skills'", dir, BODY))
  for _, f in ipairs({ 'common', 'platforms', 'spec', 'site' }) do
    sh(string.format("ln -s '%s/Config/%s' '%s/Config/%s'", real, f, dir, f))
  end
  -- every entry of a folder linked into another, but one
  local function link_all(from, to, but)
    sh(string.format("for f in '%s/'*; do [ \"$(basename \"$f\")\" = '%s' ] || ln -s \"$f\" '%s/'; done",
      from, but, to))
  end
  link_all(real .. '/Config/robots', dir .. '/Config/robots', BODY)
  link_all(real .. '/Config/robots/' .. BODY, dir .. '/Config/robots/' .. BODY, 'wbc_skills')
  for name, text in pairs(files) do
    local f = assert(io.open(string.format('%s/Config/robots/%s/wbc_skills/%s.lua', dir, BODY, name), 'w'))
    f:write(text)
    f:close()
  end
  return dir
end

describe('whole-body skills', function()
  local ctl = wbc.load({ robot = BODY })
  local function has_frame(f) return ctl:has_frame(f) end

  it('loads hello_bye: its states and rules', function()
    local s = wbc_skill.load('hello_bye', { robot = BODY, has_frame = has_frame })
    assert.equals('hello', s.initial)
    assert.same({ 'bye', 'hello', 'wave_in', 'wave_out' }, s.order)
    assert.equals(2, #s.states.wave_in.rules)
    assert.equals(2, s.states.wave_in.rules[1].times)
    assert.equals('r_palm', s.states.hello.rules[1].reached[1].task)
  end)

  it('refuses a skill naming what the body or the skill lacks, naming the file and the key', function()
    local task = "{ kind = 'position', frame = '%s', level = 2, gain = 3, max_rate = 0.15, target = { 0.2, -0.3, 1 } }"
    local dir = fake_root({
      frame = "return { initial = 'a', states = { a = { tasks = { hand = " .. task:format('r_palmm') .. " } } } }",
      joint = "return { initial = 'a', states = { a = { tasks = { posture = { kind = 'posture', level = 4, gain = 1, "
        .. "max_rate = 0.5, target = { RSP = -0.3, XYZ = 0.1 } } } } } }",
      state = "return { initial = 'a', states = { a = { next = { go = 'b', after = 1 } } } }",
      task = "return { initial = 'a', states = { a = { next = { go = 'a', reached = { hand = 0.01 } } } } }",
      kind = "return { initial = 'a', states = { a = { tasks = { com = " .. task:format('r_palm') .. " } } } }",
    })
    Config.use_root(dir)
    local file = 'Config/robots/' .. BODY .. '/wbc_skills/'
    local cases = {
      { 'frame', "'states.a.tasks.hand.frame' names 'r_palmm', which is no frame" },
      { 'joint', "'states.a.tasks.posture.target.XYZ' names no joint" },
      { 'state', "'states.a.next.go' must name a state of `states`, got 'b'" },
      { 'task', "'states.a.next.reached.hand' names no task of state 'a'" },
      { 'kind', "'states.a.tasks.com' must keep the kind" },
      { 'nosuch', "no config file for 'wbc_skills/nosuch'" },
    }
    for _, case in ipairs(cases) do
      local ok, err = pcall(wbc_skill.load, case[1], { robot = BODY, has_frame = has_frame })
      assert.is_false(ok, case[1])
      err = tostring(err)
      if case[1] ~= 'nosuch' then assert.truthy(err:find(file .. case[1] .. '.lua', 1, true), err) end
      assert.truthy(err:find(case[2], 1, true), err)
    end
    Config.use_root(nil)
    os.execute(string.format("rm -rf '%s'", dir))
  end)

  it('runs hello_bye through every state on the model (the joints following perfectly)', function()
    local c = control.new({ robot = robot, params = params, model = model })
    local link = wbc_link.new(shm.open('wbc'))
    for k = 1, 400 do tick(c, link, k) end
    c.wbc_skill, c.wbc_skill_seq = 'hello_bye', 1
    c:request('wbc')
    local seen, order = {}, {}
    for k = 1, math.floor(30 / c.dt) do
      local done = c.wbc_skill_done
      tick(c, link, k)
      if not done and c.wbc_skill_done then c.wbc_skill_error = c.wbc_skill_done.error end
      local r = c.wbc_report
      if r and r.skill_state ~= order[#order] then
        order[#order + 1] = r.skill_state
        local palm = r.by_name.r_palm
        seen[#order] = palm and palm.error or -1
      end
    end
    local moved = {}
    for i = 2, #order do moved[#moved + 1] = string.format('%.1f', seen[i] * 1e3) end
    print('# hello_bye on the model: ' .. table.concat(order, ' > ') .. '; palm error when moving on (mm): '
      .. table.concat(moved, ' '))
    for i = 2, #order do assert.is_true(seen[i] < 0.01, order[i - 1] .. ' left by time, not reached') end
    assert.is_nil(c.wbc_skill_error)
    assert.same({ 'hello', 'wave_out', 'wave_in', 'wave_out', 'wave_in', 'wave_out', 'wave_in', 'bye' }, order)
    assert.equals('hello_bye', c.wbc_report.skill)
    -- another skill asked for while it runs: it starts at once; one that cannot run is refused, naming
    -- why, and the default runs
    c.wbc_skill, c.wbc_skill_seq = 'nosuch', 2
    tick(c, link, 1)
    assert.equals(2, block_of(link).skill_done[0])
    assert.equals(-1, block_of(link).skill_rc[0])
    assert.truthy(ffi.string(block_of(link).skill_error):find("no config file for 'wbc_skills/nosuch'", 1, true))
    assert.equals('default', c.wbc_report.skill)
    assert.equals('hold', c.wbc_report.skill_state)
    c.wbc_skill, c.wbc_skill_seq = 'hello_bye', 3
    tick(c, link, 2)
    assert.equals(0, block_of(link).skill_rc[0])
    assert.equals('hello', ffi.string(block_of(link).skill_state))
    assert.is_true(c.wbc_report.by_name.r_palm.enabled)
    c.wbc_skill, c.wbc_skill_seq = nil, 4   -- the default again: the palm's task rests
    tick(c, link, 3)
    assert.equals('default', ffi.string(block_of(link).skill))
    assert.is_false(c.wbc_report.by_name.r_palm.enabled)
  end)
end)
