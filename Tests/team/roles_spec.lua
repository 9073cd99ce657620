-- luacheck: std +busted
-- Roles from shared estimates (Player/Team/roles.lua) and their positions (Team/position.lua); then
-- a behavior that hears a teammate over UDP: it defends while the teammate strikes, and takes the
-- striker's role over when the teammate is lost.
local shm = require('shm')
local view = require('Tests.behavior.view')
local roles = require('Team.roles')
local position = require('Team.position')
local Team = require('Team.team')
local Config = require('Config')

local rules = Config.load('game')
local field = Config.load('behavior').world.field
local GOAL_X = -field.length / 2
local function cfg(keeper, keeper_team)
  return setmetatable({ goalkeeper = keeper or 0, keeper_team = keeper_team }, { __index = rules.roles })
end
local function r(player, x, y, a) return { player = player, pose = { x, y, a or 0 } } end

describe('roles', function()
  local ball = { 1.0, 0.0 }
  local team = { r(2, 0.2, 0.1), r(3, -2.0, 1.0), r(4, -3.5, -0.5) }

  it('goalkeeper as designated, striker first to the ball, defender nearest the own goal', function()
    local role, all = roles.assign(r(1, -4.2, 0), team, cfg(1), ball, GOAL_X)
    assert.are.equal('goalkeeper', role)
    assert.are.same({ [1] = 'goalkeeper', [2] = 'striker', [3] = 'supporter', [4] = 'defender' }, all)
  end)

  it('the time to the ball counts the turn', function()
    local facing = roles.time_to_ball(r(1, 0, 0, 0), ball, rules.roles)
    local away = roles.time_to_ball(r(1, 0, 0, math.pi), ball, rules.roles)
    assert.is_true(math.abs(facing - 1.0 / rules.roles.walk_speed) < 1e-9)
    assert.is_true(math.abs(away - facing - math.pi / rules.roles.turn_speed) < 1e-9)
  end)

  it("a lost striker's role is taken over by the next fastest", function()
    local _, all = roles.assign(r(1, -4.2, 0), { team[2], team[3] }, cfg(1), ball, GOAL_X)
    assert.are.same({ [1] = 'goalkeeper', [3] = 'striker', [4] = 'defender' }, all)
  end)

  it("a lost goalkeeper's role is taken over by the robot nearest the own goal, when two others remain", function()
    local _, all = roles.assign(r(2, 0.2, 0.1), { team[2], team[3] }, cfg(1), ball, GOAL_X)
    assert.are.same({ [2] = 'striker', [3] = 'defender', [4] = 'goalkeeper' }, all)
    _, all = roles.assign(r(2, 0.2, 0.1), { team[3] }, cfg(1), ball, GOAL_X)
    assert.are.same({ [2] = 'striker', [4] = 'defender' }, all)
  end)

  it('two robots are a striker and a defender, the designated goalkeeper among them (keeper_team 3)', function()
    assert.are.equal(3, rules.roles.keeper_team)
    local role, all = roles.assign(r(1, -4.2, 0), { team[1] }, cfg(1), ball, GOAL_X)
    assert.are.equal('defender', role)
    assert.are.same({ [1] = 'defender', [2] = 'striker' }, all)
    -- the designated goalkeeper nearer the ball strikes
    all = select(2, roles.assign(r(1, 0.8, 0), { team[3] }, cfg(1), ball, GOAL_X))
    assert.are.same({ [1] = 'striker', [4] = 'defender' }, all)
    -- a third robot back: the goalkeeper keeps goal again
    all = select(2, roles.assign(r(1, 0.8, 0), { team[3], team[1] }, cfg(1), ball, GOAL_X))
    assert.are.equal('goalkeeper', all[1])
  end)

  it('a robot alone strikes, even the designated goalkeeper; penalised teammates do not count', function()
    assert.are.equal('striker', (roles.assign(r(1, -4.2, 0), {}, cfg(1), ball, GOAL_X)))
    local pen = r(2, 0.2, 0.1)
    pen.penalised = true
    assert.are.equal('striker', (roles.assign(r(3, -2, 1), { pen }, cfg(0), ball, GOAL_X)))
  end)

  it('the striker keeps the ball until another is faster by the margin', function()
    local rc = rules.roles
    local me = r(1, 0.0, 0.0)
    local a_bit = r(2, 0.5 * rc.striker_margin * rc.walk_speed, 0.0) -- half the margin faster
    local much = r(2, 2.0 * rc.striker_margin * rc.walk_speed, 0.0)  -- twice the margin faster
    local was_mate = { [1] = 'defender', [2] = 'striker' }
    local was_me = { [1] = 'striker', [2] = 'defender' }
    assert.are.equal('defender', (roles.assign(me, { a_bit }, cfg(0), ball, GOAL_X, was_mate)))
    assert.are.equal('striker', (roles.assign(me, { a_bit }, cfg(0), ball, GOAL_X, was_me)))
    assert.are.equal('defender', (roles.assign(me, { much }, cfg(0), ball, GOAL_X, was_me)))
    -- the teammate, computing from the same data, agrees in each case
    assert.are.equal('striker', (roles.assign(a_bit, { me }, cfg(0), ball, GOAL_X, was_mate)))
    assert.are.equal('defender', (roles.assign(a_bit, { me }, cfg(0), ball, GOAL_X, was_me)))
    -- another robot joined since: a fresh choice (the faster one), the margin not carried over
    local third = r(3, -3.0, 2.0)
    local all = select(2, roles.assign(me, { a_bit, third }, cfg(0), ball, GOAL_X, was_me))
    assert.are.same({ [1] = 'supporter', [2] = 'striker', [3] = 'defender' }, all)
  end)

  it("a teammate's time to the ball from the ball it reports: two robots with their own balls agree", function()
    -- robot 1 sees the ball at 1.0 m, robot 2 (facing it from 2 m) at 1.4 m; each reports its own
    local one, two = r(1, 0.0, 0.0, 0.0), r(2, 2.0, 0.0, math.pi)
    one.ball, one.ball_known = { 1.0, 0.0 }, true
    two.ball, two.ball_known = { 1.4, 0.0 }, true
    local _, one_view = roles.assign(one, { two }, cfg(0), one.ball, GOAL_X)
    local _, two_view = roles.assign(two, { one }, cfg(0), two.ball, GOAL_X)
    assert.are.same({ [1] = 'defender', [2] = 'striker' }, one_view)
    assert.are.same(one_view, two_view)
  end)

  it('two robots that both were strikers settle on one: the lower number a teammate hears strike', function()
    local rc = rules.roles
    -- robot 2 a little faster to the ball than robot 1, each remembering itself as the striker
    local one, two = r(1, 0.0, 0.0), r(2, 0.5 * rc.striker_margin * rc.walk_speed, 0.0)
    local function says_strike(x) -- its message: its ball, its target at the ball
      x.ball, x.ball_known, x.target = { ball[1], ball[2] }, true, { ball[1], ball[2], 0 }
      return x
    end
    says_strike(one)
    says_strike(two)
    local one_view = { [1] = 'striker', [2] = 'defender' }
    local two_view = { [1] = 'defender', [2] = 'striker' }
    assert.are.equal('striker', (roles.assign(one, { two }, cfg(0), ball, GOAL_X, one_view)))
    assert.are.equal('defender', (roles.assign(two, { one }, cfg(0), ball, GOAL_X, two_view)))
    -- a teammate whose target is its place, not its ball, does not strike: robot 2 keeps its margin
    local placed = r(1, 0.0, 0.0)
    placed.ball, placed.ball_known = { ball[1], ball[2] }, true
    placed.target = { GOAL_X + 1.5, 0.0, 0 }
    assert.are.equal('striker', (roles.assign(two, { placed }, cfg(0), ball, GOAL_X, two_view)))
    -- no ball in its message: no claim either
    local blind = r(1, 0.0, 0.0)
    blind.target = { ball[1], ball[2], 0 }
    assert.are.equal('striker', (roles.assign(two, { blind }, cfg(0), ball, GOAL_X, two_view)))
  end)

  it('a striker that is down gives the ball to an upright teammate near it, not to one far away', function()
    local rc = rules.roles
    local striker = r(1, ball[1] - 0.1, 0.0)                    -- at the ball
    local near = r(2, ball[1] - 1.0, 0.0)                       -- a metre short of it, facing it
    local was = { [1] = 'striker', [2] = 'defender' }
    assert.are.equal('defender', (roles.assign(near, { striker }, cfg(0), ball, GOAL_X, was)))
    striker.fallen = true
    -- both compute the same: the teammate takes the ball, the one lying down defends
    assert.are.equal('striker', (roles.assign(near, { striker }, cfg(0), ball, GOAL_X, was)))
    assert.are.equal('defender', (roles.assign(striker, { near }, cfg(0), ball, GOAL_X, was)))
    -- its claim (target at its ball) does not count while it is down
    striker.ball, striker.ball_known, striker.target = { ball[1], ball[2] }, true, { ball[1], ball[2], 0 }
    assert.are.equal('striker', (roles.assign(near, { striker }, cfg(0), ball, GOAL_X, was)))
    -- a teammate further than fallen_time's walk: the one lying at the ball keeps it
    local far_x = ball[1] - (rc.fallen_time + 1.0) * rc.walk_speed
    local far = r(2, far_x, 0.0)
    assert.are.equal('defender', (roles.assign(far, { striker }, cfg(0), ball, GOAL_X, was)))
    -- up again once the teammate has reached the ball: the new striker keeps it (the margin is its own)
    striker.fallen = false
    striker.target = { GOAL_X + 1.5, 0.0, 0 } -- it defends since it went down: its place, not the ball
    near.pose[1] = ball[1] - 0.2
    local now = { [1] = 'defender', [2] = 'striker' }
    assert.are.equal('striker', (roles.assign(near, { striker }, cfg(0), ball, GOAL_X, now)))
  end)

  it('the goalkeeper clears a ball near its goal only when first to it; the striker then waits upfield', function()
    -- a goalkeeper in a team of two (keeper_team 2: the rule, whatever the team size)
    local rc = rules.roles
    local near = { GOAL_X + 1.0, 0.4 }
    local keeper, chaser = r(1, GOAL_X + 0.5, 0, 0), r(2, GOAL_X + 2.5, 0.4, math.pi)
    local keeper_striker = { [1] = 'goalkeeper', [2] = 'striker' } -- the last assignment
    local role, all, clearing = roles.assign(keeper, { chaser }, cfg(1, 2), near, GOAL_X)
    assert.are.equal('goalkeeper', role)
    assert.are.same({ [1] = 'goalkeeper', [2] = 'striker' }, all)
    assert.is_true(clearing)
    -- the teammate computes the same
    assert.is_true(select(3, roles.assign(chaser, { keeper }, cfg(1, 2), near, GOAL_X, keeper_striker)))
    assert.is_nil(position.target('goalkeeper', near, rc, field, true))
    local x, y = position.target('striker', near, rc, field, true)
    assert.are.equal(near[1] + rc.receive_ahead, x)
    assert.is_true(math.abs(y) < near[2])
    -- the striker at the ball, the goalkeeper further: the goalkeeper keeps its place
    local at_ball = r(2, GOAL_X + 1.1, 0.4, math.pi)
    clearing = select(3, roles.assign(keeper, { at_ball }, cfg(1, 2), near, GOAL_X))
    assert.is_false(clearing)
    assert.is_not_nil(position.target('goalkeeper', near, rc, field, false))
    assert.is_nil(position.target('striker', near, rc, field, false))
    -- a little faster than the clearing goalkeeper is not enough to take the ball from it
    local a_bit = r(2, GOAL_X + 1.0 + 0.5 * rc.striker_margin * rc.walk_speed + 0.5, 0.4, math.pi)
    local tk = roles.time_to_ball(keeper, near, rc)
    assert.is_true(roles.time_to_ball(a_bit, near, rc) < tk, 'the teammate is faster')
    assert.is_true(select(3, roles.assign(keeper, { a_bit }, cfg(1, 2), near, GOAL_X, keeper_striker, true)))
    -- a ball far from the goal is never the goalkeeper's
    clearing = select(3, roles.assign(keeper, { chaser }, cfg(1, 2), { 0, 0 }, GOAL_X))
    assert.is_false(clearing)
  end)

  it('positions: goalkeeper on the goal-ball line, defender short of the ball, supporter behind and inside', function()
    local rc = rules.roles
    local x, y = position.target('goalkeeper', { -2.0, 2.0 }, rc, field)
    assert.is_true(x > GOAL_X and x < GOAL_X + rc.keeper_depth + 1e-9)
    assert.is_true(y > 0 and y <= field.goal_width / 2)
    assert.is_nil(position.target('goalkeeper', { GOAL_X + 0.5, 0.2 }, rc, field, true)) -- clears a near ball
    -- a ball lying on the goal line beside the goal's centre, or behind it: the goalkeeper's place stays
    -- keeper_min_depth in front of the line (not on the line, into the ball)
    for _, b in ipairs({ { GOAL_X + 0.03, 0.31 }, { GOAL_X - 0.2, 0.5 }, { GOAL_X, -1.0 } }) do
      x = position.target('goalkeeper', b, rc, field)
      assert.is_near(GOAL_X + rc.keeper_min_depth, x, 1e-9)
    end
    assert.is_nil(position.target('striker', ball, rc, field))
    -- the defender: on the goal-ball line, defender_gap short of the ball; near the goal no nearer
    -- to it than keeper_depth
    x, y = position.target('defender', { 2.0, 1.0 }, rc, field)
    local bx, by = 2.0 - GOAL_X, 1.0
    local d = math.sqrt(bx * bx + by * by)
    assert.is_near(2.0 - rc.defender_gap * bx / d, x, 1e-9)
    assert.is_near(1.0 - rc.defender_gap * by / d, y, 1e-9)
    x, y = position.target('defender', { GOAL_X + 0.8, 0.6 }, rc, field)
    assert.is_near(rc.keeper_depth, math.sqrt((x - GOAL_X) ^ 2 + y ^ 2), 1e-9)
    x, y = position.target('supporter', { 3.0, -2.7 }, rc, field)
    assert.are.equal(3.0 - rc.supporter_back, x)
    assert.is_true(y > -2.7 and y <= field.width / 2 - rc.field_margin)
  end)

  it('kick-off positions in READY by role; supporters on either side by player number', function()
    local rc, striker = rules.roles, { -1, 0, 0 }
    assert.are.equal(striker, position.ready('striker', 2, rc, striker))
    assert.are.same(rc.ready.goalkeeper, position.ready('goalkeeper', 1, rc, striker))
    assert.are.same(rc.ready.defender, position.ready('defender', 3, rc, striker))
    local a, b = position.ready('supporter', 2, rc, striker), position.ready('supporter', 3, rc, striker)
    assert.are.equal(a[1], b[1])
    assert.are.equal(-a[2], b[2])
    assert.is_true(a[2] ~= 0)
  end)
end)

describe('roles in the behavior', function()
  local id = tonumber(os.getenv('ROBOT_ID') or '1')
  local port = 23000 + (id % 20000)
  local sensor, vision, motion, game, behavior, mate
  local tc = setmetatable({ broadcast = '127.255.255.255' }, { __index = rules.team })

  setup(function()
    sensor, vision = shm.open('dcm.sensor'), shm.open('vision')
    motion, game = shm.open('motion'), shm.open('game')
    sensor.time[0], sensor.tick[0] = 200, 0
    behavior = require('Behavior.behavior').new({ port = 0, team_port = port, fresh = true })
    mate = Team.new({ team_number = 1, player_number = 2, team = tc }, { port = port })
  end)
  teardown(function()
    behavior:close()
    mate:close()
    if os.getenv('ROBOT_ID') then for _, name in ipairs(shm.block_names()) do shm.unlink(name) end end
  end)

  -- the robot sees the ball 2 m ahead and the opponent goal's posts as from (-2, 0); the teammate
  -- (while `talking`) says it stands 0.3 m from the ball at (0, 0.1), facing it
  local tick = 0
  local function run(seconds, talking)
    for _ = 1, math.floor(seconds / 0.024 + 0.5) do
      tick = view.frame(sensor, vision, tick, 2.0, 0.1)
      if talking then
        mate:update(sensor.time[0], { pose = { -0.3, 0.1, 0 }, ball = { 0.0, 0.1, 0, 0 }, penalised = false,
          walk = { 0, 0, 0 } })
      end
      behavior:step()
    end
  end

  it('defends while a teammate nearer the ball strikes, and strikes once the teammate is lost', function()
    run(3, true)
    assert.are.equal(1, #behavior.world.mates)
    assert.are.equal(roles.INDEX.defender, game.role[0])
    assert.are.equal('idle', behavior.body:state()) -- not going for the ball: keeping its position
    assert.is_true(math.abs(motion.velocity[0]) + math.abs(motion.velocity[1]) + math.abs(motion.velocity[2]) > 0)
    run(rules.team.lost_after - 0.5, false)
    assert.are.equal(roles.INDEX.defender, game.role[0]) -- not yet lost
    run(1.0, false)
    assert.are.equal(0, #behavior.world.mates)
    assert.are.equal(roles.INDEX.striker, game.role[0])
    assert.are_not.equal('idle', behavior.body:state())
  end)
end)
