-- luacheck: std +busted
-- Joint trajectory files (Lib/trajectory.lua): a file for the body loads and interpolates; one that
-- does not fit the body, or holds a value that is not a finite number, is refused naming its line;
-- the motion controller refuses such a file at the request and plays a good one, then stance.
local Config = require('Config')
local kin = require('kinematics')
local control = require('Motion.control')
local trajectory = require('trajectory')

local robot = { name = 'tiny', joints = { 'a', 'b', 'c' } }

local function text(lines) return table.concat(lines, '\n') .. '\n' end
local GOOD = { '# hrp joint trajectory', '# robot tiny', '# dt 0.1', '# joints 3', 't,c,a,b,zmp_x',
  '0,3,1,2,0.5', '0.1,6,2,4,0.7' }
local function with(k, line)
  local l = { unpack(GOOD) }
  l[k] = line
  return text(l)
end

describe('trajectory files', function()
  it('loads a file in any joint order and interpolates the joints and the other columns', function()
    local tr = trajectory.parse(text(GOOD), 'good.csv', robot)
    assert.are.equal(0.1, tr.duration)
    local q = tr:joints_at(0.05, {})
    assert.is_true(math.abs(q[1] - 1.5) < 1e-12 and math.abs(q[2] - 3) < 1e-12 and math.abs(q[3] - 4.5) < 1e-12)
    assert.is_true(math.abs(tr:extra_at('zmp_x', 0.05) - 0.6) < 1e-12)
    assert.are.same({ 2, 4, 6 }, tr:joints_at(5, {})) -- past the end: the last row
  end)

  local function refused(src, pattern)
    local ok, err = pcall(trajectory.parse, src, 'bad.csv', robot)
    assert.is_false(ok)
    assert.is_truthy(tostring(err):find(pattern, 1, true), tostring(err))
  end
  it('refuses a NaN or an infinity, naming the line and the column', function()
    refused(with(7, '0.1,6,nan,4,0.7'), "bad.csv:7: column 'a'")
    refused(with(6, '0,3,1,2,inf'), "bad.csv:6: column 'zmp_x'")
  end)
  it('refuses joint names or a count that do not match the body', function()
    refused(with(4, '# joints 2'), 'bad.csv:5: 2 joint columns, the body tiny has 3 joints')
    refused(with(5, 't,c,a,x,zmp_x'), "bad.csv:5: column 4 'x' is not a joint of the body tiny")
    refused(with(5, 't,c,a,a,zmp_x'), "bad.csv:5: joint 'a' named twice")
  end)
  it('refuses short rows and times that do not increase', function()
    refused(with(7, '0.1,6,2,4'), 'bad.csv:7: 4 values')
    refused(with(7, '0,6,2,4,0.7'), 'bad.csv:7: times must start at 0 and increase')
  end)
  it('writes what it reads', function()
    local path = os.tmpname()
    trajectory.write(path, { robot = 'tiny', dt = 0.1, joints = { 'b', 'a', 'c' }, extra = { 'zmp_x' },
      rows = { { 0, 1, 2, 3, 0 }, { 0.1, 2, 3, 4, 1 } } })
    local tr = trajectory.load(path, robot)
    os.remove(path)
    assert.are.same({ 3, 2, 4 }, tr:joints_at(0.1, {}))
  end)
end)

describe('the motion state pattern', function()
  local body = Config.load('robot')
  local c = control.new({ robot = body, params = Config.load('walk'), model = kin.load() })
  local n = c.n
  local function tick()
    for i = 1, n do c.pos[i] = c.q[i] end
    c:tick(c.t + body.period)
  end
  local function file(rows)
    local path = os.tmpname()
    local extra = {}
    trajectory.write(path, { robot = body.name, dt = 0.1, joints = body.joints, extra = extra, rows = rows })
    return path
  end
  local function row(t, v)
    local r = { t }
    for i = 1, n do r[i + 1] = v end
    return r
  end

  it('refuses a file for another body and keeps the wish it had', function()
    for _ = 1, 10 do tick() end
    local ok, err = c:request('pattern', { file = 'Tests/motion/nonexistent.csv' })
    assert.is_false(ok)
    assert.is_truthy(err:find('nonexistent.csv', 1, true))
    assert.are.equal('stand', c.want)
  end)

  it('blends into the first row, plays the rows, then goes back to stance', function()
    for _ = 1, math.floor(3 / body.period) do tick() end
    assert.are.equal('stance', c:state())
    local path = file({ row(0, 0.01), row(0.5, 0.03) })
    assert.is_true(c:request('pattern', { file = path }))
    os.remove(path)
    tick()
    assert.are.equal('pattern', c:state())
    local blend = Config.load('pattern').blend
    while (c.pattern_time or -1) < 0.25 do tick() end
    assert.is_true(c.pattern_time - 0.25 < body.period + 1e-9)
    local expect = 0.01 + 0.02 * c.pattern_time / 0.5
    for i = 1, n do assert.is_true(math.abs(c.q[i] - expect) < 1e-9) end
    assert.is_true(c:since() >= blend)
    for _ = 1, math.floor(1 / body.period) do tick() end
    assert.are.equal('stance', c:state())
    assert.is_nil(c.pattern_time)
    assert.are.equal('stand', c.want)
  end)
end)
