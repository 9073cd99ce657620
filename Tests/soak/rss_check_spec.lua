-- luacheck: std +busted
-- The soak's memory check (Tests/soak/rss_check.lua) on made-up series, sampled every 30 s from 210 s to
-- 600 s as the 10-minute soak's are after its warm-up: a leak of 1 kB per simulated second fails it,
-- one-time steps and a garbage collector's sawtooth do not.
local check = require('Tests.soak.rss_check')

local function series(f)
  local s = {}
  for t = 0, 600, 30 do s[#s + 1] = { t = t, kb = math.floor(f(t)) } end
  return s
end
local function pages(kb) return 4 * math.floor(kb / 4) end   -- RSS moves in 4 kB pages
local DCM = 0.25

describe('the soak RSS check', function()
  it('passes a flat series with one-time steps (a blur buffer at a restart, an arena)', function()
    local ok, line = check.judge('dcm', series(function(t)
      return 13400 + (t >= 390 and 2056 or 0) + (t >= 540 and 300 or 0)
    end), 210, DCM)
    assert.is_true(ok, line)
    assert.truthy(line:find('+2056 KB at t=360-390', 1, true), line)
  end)

  it('fails a leak of 1 kB per simulated second', function()
    local ok, line = check.judge('dcm', series(function(t) return 13400 + pages(t * 1.024) end), 210, DCM)
    assert.is_false(ok, line)
    local rate = check.rate(series(function(t) return 13400 + pages(t * 1.024) end), 2)
    assert.is_true(rate > 0.7, tostring(rate))
  end)

  it('fails the leak with one-time steps on top of it', function()
    local ok, line = check.judge('dcm', series(function(t)
      return 13400 + pages(t * 1.024) + (t >= 390 and 2056 or 0) + (t >= 300 and 600 or 0)
    end), 210, DCM)
    assert.is_false(ok, line)
  end)

  it('fails a leak that comes in bursts (60 kB a minute)', function()
    local ok, line = check.judge('dcm', series(function(t) return 13400 + 60 * math.floor(t / 60) end), 210, DCM)
    assert.is_false(ok, line)
  end)

  it('passes a garbage collector sawtooth, and sees a leak on top of it at the Lua bound', function()
    local saw = function(t) return 9500 + ((t / 30) % 3) * 150 end
    assert.is_true((check.judge('motion', series(saw), 210, 4)))
    assert.is_false((check.judge('motion', series(function(t) return saw(t) + pages(t * 6) end), 210, 4)))
  end)

  it('counts a sample as warm-up only before the warm-up ends, and needs samples after it', function()
    local ok, line = check.judge('dcm', series(function() return 1000 end), 210, DCM)
    assert.is_true(ok, line)
    assert.truthy(line:find('(1000) 1000', 1, true), line)
    assert.is_false((check.judge('dcm', series(function() return 1000 end), 550, DCM)))
  end)

  it('parses the sampler lines and sees a restarted process', function()
    local lines = {
      'proc dcm t=0 pid=10 rss_kb=100 anon_kb=1 huge_kb=0 fds=5 shm=6',
      'robot t=0 segments=17 games=0 falls=0',
      'proc dcm t=30 pid=10 rss_kb=120 anon_kb=1 huge_kb=0 fds=5 shm=6',
      'proc motion t=30 pid=11 rss_kb=90 anon_kb=1 huge_kb=0 fds=5 shm=6',
      'proc motion t=60 pid=12 rss_kb=90 anon_kb=1 huge_kb=0 fds=5 shm=6',
    }
    local i = 0
    local procs, order = check.parse(function() i = i + 1 return lines[i] end)
    assert.same({ 'dcm', 'motion' }, order)
    assert.same({ { t = 0, kb = 100 }, { t = 30, kb = 120 } }, procs.dcm.all)
    assert.equal(1, procs.dcm.npids)
    assert.equal(2, procs.motion.npids)
  end)
end)
