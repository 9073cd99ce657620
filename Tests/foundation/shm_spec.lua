-- luacheck: std +busted
-- Shared memory across processes and languages: C writer / Lua reader and the reverse,
-- consistency under concurrent writing, the Python reader, layout errors.
local shm = require('shm')
local native = require('native')

local peer = native.root() .. '/build/bin/shm_c_peer'

local function run(cmd)
  local h = io.popen(cmd .. ' 2>&1; echo "rc=$?"')
  local out = h:read('*a')
  h:close()
  local rc = tonumber(out:match('rc=(%d+)%s*$'))
  return out:gsub('rc=%d+%s*$', ''), rc
end

describe('shm', function()
  local sensor = shm.open('dcm.sensor')

  it('gives typed arrays straight into the segment', function()
    assert.equal('cdata', type(sensor.position))
    sensor.position[3] = 1.25
    assert.equal(1.25, sensor:get('position')[4])
    assert.equal(32, sensor:count('position')) -- const njoint: room for the largest body
    assert.has_error(function() sensor:get('nope') end, "shm block 'dcm.sensor' has no field 'nope'")
  end)

  it('a C writer in another process is seen by Lua', function()
    local out, rc = run(peer .. ' write dcm.sensor gyro 0.5 -1.5 2.25')
    assert.equal(0, rc, out)
    assert.same({ 0.5, -1.5, 2.25 }, sensor:get('gyro'))
  end)

  it('a Lua write is seen by a C reader in another process', function()
    sensor:write(function(s) s.accelerometer[0] = 0.125; s.accelerometer[2] = 9.81 end)
    local out, rc = run(peer .. ' read dcm.sensor accelerometer')
    assert.equal(0, rc)
    assert.equal('0.125 0 9.8100000000000005', out:match('[^\n]+'))
  end)

  it('a Lua reader never sees a half-done multi-field update of a C writer', function()
    sensor:write(function(s) s:set('gyro', 0); s.tick[0] = 0 end)   -- a consistent start
    local writer = io.popen(peer .. ' stream dcm.sensor 400000 2>&1')
    local reads, torn = 0, 0
    local t_end = shm.C.shm_now() + 20
    repeat
      local g0, g1, g2, tick = sensor:read(function(s) return s.gyro[0], s.gyro[1], s.gyro[2], s.tick[0] end)
      reads = reads + 1
      if g1 ~= 2 * g0 or g2 ~= 3 * g0 or tick ~= g0 then torn = torn + 1 end
    until tick == 400000 or shm.C.shm_now() > t_end
    writer:close()
    print(string.format('# %d Lua reads during 400000 C writes, %d torn', reads, torn))
    assert.equal(0, torn)
    assert.equal(400000, sensor.tick[0])
  end)

  it('a C reader never sees a half-done multi-field update of a Lua writer', function()
    local checker = io.popen(peer .. ' check dcm.sensor 1.5 2>&1; echo "rc=$?"')
    local t_end = shm.C.shm_now() + 1.6
    local k = 0
    while shm.C.shm_now() < t_end do
      k = k + 1
      sensor:write(function(s) s.gyro[0] = k; s.gyro[1] = 2 * k; s.gyro[2] = 3 * k; s.tick[0] = k end)
    end
    local out = checker:read('*a')
    checker:close()
    print('# C checker: ' .. out:gsub('\n', ' ') .. ' during ' .. k .. ' Lua writes')
    assert.truthy(out:find('torn 0', 1, true), out)
    assert.truthy(out:find('rc=0', 1, true), out)
  end)

  it('the Python reader finds fields by name from the segment alone', function()
    sensor:write(function(s) s.time[0] = 3.5; s.angle[0] = -0.25; s.tick[0] = 77 end)
    local out, rc = run('python3 ' .. native.root() .. '/Run/view/shm_read.py dcm.sensor angle')
    assert.equal(0, rc, out)
    assert.truthy(out:find('angle -0.25 0.0 0.0', 1, true), out)
    out = run('python3 ' .. native.root() .. '/Run/view/shm_read.py dcm.sensor tick')
    assert.truthy(out:find('tick 77', 1, true), out)
  end)

  it('a reader of a block whose writer died mid-update gets an error naming it, not a spin', function()
    local bench = shm.open('bench')
    local out, rc = run([[luajit -e "local b = require('shm').open('bench'); b:begin_write(); os.exit(0)"]])
    assert.equal(0, rc, out)
    local t0 = shm.C.shm_now()
    local ok, err = pcall(bench.read, bench, function(b) return b.k[0] end)
    assert.is_false(ok)
    assert.matches("shm block 'bench' is stale: its writer %(pid %d+%) died mid%-update", err)
    assert.is_true(shm.C.shm_now() - t0 < 1.0)
    bench:write(function(b) b.k[0] = 1 end) -- the next writer takes over: whole again
    assert.equal(1, bench:read(function(b) return b.k[0] end))
  end)

  it('an unknown block is an error that names it', function()
    local ok, err = pcall(shm.open, 'no.such.block')
    assert.is_false(ok)
    assert.truthy(err:find("unknown block 'no.such.block'", 1, true))
  end)

  it('the shm tool lists, dumps, sets and removes a robot\'s blocks', function()
    local robot = shm.robot_id() + 50000
    local tool = native.root() .. '/Tools/shm/shm --robot ' .. robot
    local b = shm.open('world', { robot = robot })
    b:set('pose', { 1, 2, 3 })
    local out = run(tool .. ' list')
    assert.truthy(out:find('world', 1, true), out)
    run(tool .. ' set world pose_confidence 0.75')
    assert.equal(0.75, b.pose_confidence[0])
    out = run(tool .. ' dump world pose')
    assert.truthy(out:find('pose%s+f64%s*%[3%]%s+1 2 3'), out)
    out = run(tool .. ' remove')
    assert.truthy(out:find('removed 1 blocks', 1, true), out)
    assert.is_nil((shm.open('world', { robot = robot + 1, attach = true, try = true })))
  end)

  it('a process that keeps a removed or recreated block can tell (Block:replaced)', function()
    local robot = shm.robot_id() + 50001
    local old = shm.open('world', { robot = robot })
    assert.is_false(old:replaced())
    shm.unlink("world", robot)
    assert.is_true(old:replaced())
    local new = shm.open('world', { robot = robot })
    assert.is_true(old:replaced())
    assert.is_false(new:replaced())
    shm.unlink("world", robot)
  end)

  it('lists the replaced blocks a process holds and maps one again in place (Block:reopen)', function()
    local robot = shm.robot_id() + 50002
    local w = shm.open('world', { robot = robot })
    local g = shm.open('game', { robot = robot })
    w.ball_time[0] = 4.5
    local function names()
      local list = {}
      for _, b in ipairs(shm.replaced()) do if b._robot == robot then list[#list + 1] = b:name() end end
      return list
    end
    assert.are.same({}, names())
    shm.C.shm_block_unlink('world', robot) -- removed by someone else: this process's cache keeps it
    assert.are.same({ 'world' }, names())
    local old_ptr = w.ball_time
    assert.is_true(w:reopen())
    assert.are.same({}, names())
    assert.are.equal(0, w.ball_time[0])         -- the new segment
    assert.are.equal(4.5, old_ptr[0])           -- a pointer taken before stays on the old one
    w.ball_time[0] = 1.25
    assert.are.equal(1.25, shm.open('world', { robot = robot, raw = true }).ball_time[0])
    assert.is_false(g:replaced())
    shm.unlink('world', robot)
    shm.unlink('game', robot)
  end)

  it('shm_watch: a process exits naming the replaced block; a supervisor maps it again', function()
    local watch = require('shm_watch')
    local robot = shm.robot_id() + 50003
    local v = shm.open('vision', { robot = robot })
    local said
    local check = watch.exit_on_replaced('vision', { period = 0, robot = robot, exit = function(msg) said = msg end })
    check()
    assert.is_nil(said)
    shm.C.shm_block_unlink('vision', robot)
    check()
    assert.are.equal('vision: shm block(s) vision replaced under this process (removed or recreated): ' ..
      'exiting for a restart', said)
    local logged = {}
    local reopen = watch.reopen_replaced(function(fmt, ...) logged[#logged + 1] = string.format(fmt, ...) end,
      { period = 0, robot = robot })
    reopen()
    assert.are.same({ 'shm block vision was replaced: mapped again' }, logged)
    assert.is_false(v:replaced())
    shm.unlink('vision', robot)
  end)
end)
