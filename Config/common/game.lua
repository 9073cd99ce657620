-- The game: the GameController, kick-off and set-play rules, team communication. Rule numbers are
-- the RoboCup Humanoid League's (KidSize; Laws of the Game 2019 onwards: 0.75 m for the opponents
-- at free kicks and the centre circle's radius at kick-off); a venue or a league changes them here.
-- Units: metres, seconds.
return {
  gamecontroller = {
    port = 3838,               -- UDP: the GameController's packets (RGme, HL version 12)
    return_port = 3939,        -- UDP: our return packets (RGrt version 2), to the sender's address
    -- the network interface the GameController's packets come in on (the robot's team network;
    -- '' = every interface); datagrams from anywhere else never reach the listener
    interface = 'wlan0',
    hosts = {},                -- the GameController's addresses ("10.0.0.2"); {}: any host on `interface`
    alive_period = 1.0,        -- s (robot clock) between "alive" return packets
    -- with no GameController packet seen: 'initial' waits there until a packet or the chest button
    -- (a real robot beside a real field); 'playing' starts playing `start_delay` s after start-up
    -- (the simulator's quick start: Config/platforms/Sim/game.lua)
    start_without = 'initial',
    start_delay = 2.0,
  },
  kickoff = {
    -- the team without the kick-off stays outside the centre circle until the ball has moved or
    -- `wait` s of PLAYING have passed
    wait = 10.0,
    distance = 0.75,           -- m from the ball (the centre circle's radius)
    ball_moved = 0.3,          -- m the ball's estimate must move (its sightings' error at 1-2 m)
  },
  setplay = {
    -- m the opponents of the team taking a set play keep from the ball (Humanoid League KidSize)
    distance = { direct_free_kick = 0.75, indirect_free_kick = 0.75, corner_kick = 0.75,
      goal_kick = 0.75, throw_in = 0.75,
      penalty_kick = 1.5 },    -- the penalty mark's own rule; conservative: outside the penalty area
    margin = 0.15,             -- m kept beyond the distance (the ball estimate's error)
    hysteresis = 0.2,          -- m: nearer than distance + margin: back off; beyond + this: stand
    retreat_speed = 0.15,      -- m/s backing away from the ball
    turn_gain = 0.8,           -- 1/s: turning to face the ball while keeping away
    take_tolerance = 0.1,      -- m: standing behind the ball for our own set play, this near the spot
    keeper_line = 0.15,        -- m in front of its goal line: our goalkeeper at their penalty kick
  },
  team = {
    enabled = true,            -- false: no messages sent or read (with roles.enabled = false: each
                               -- robot plays alone; Tools/match/match.sh's ALONE, Tools/match/league.py)
    port_base = 10000,         -- UDP: each team broadcasts on port_base + its team number
    broadcast = '255.255.255.255',
    interface = 'wlan0',       -- the team network (as gamecontroller.interface)
    hosts = {},                -- the teammates' addresses; {}: any host on `interface`
    period = 0.5,              -- s (robot clock) between our messages
    lost_after = 3.0,          -- s without a message: the teammate is lost (its role is taken over)
    max_per_step = 32,         -- datagrams read per behavior step (a flood cannot stall the behavior)
    max_players = 11,          -- player numbers 1..11 (the GameController's; the team shm block's size)
  },
  -- roles from the shared estimates (Player/Team/roles.lua) and where each stands (Team/position.lua)
  roles = {
    enabled = true,            -- false: every robot plays the ball alone
    goalkeeper = 0,            -- player number of the goalkeeper without a GameController (0: none;
                               -- with one, its goalKeeper flag decides)
    keeper_team = 3,           -- robots playing from which the goalkeeper keeps goal (fewer: striker and
                               -- defender; in 2v2 a goalkeeper loses more than it saves: tuning.md)
    walk_speed = 0.2,          -- m/s and rad/s a robot is assumed to walk and turn at (time to the ball)
    turn_speed = 0.5,
    striker_margin = 1.5,      -- s: the striker keeps the ball until another is this much faster
    striking_radius = 0.3,     -- m: a teammate's target this near its ball: it says it goes for the ball
    fallen_time = 8,           -- s a robot that is down needs before it walks again (time to the ball;
                               -- a fallen OP3 lies 2-17 s, median 5.3 s, before it stands up)
    keeper_depth = 0.5,        -- m out from the own goal's centre towards the ball
    keeper_min_depth = 0.3,    -- m: the goalkeeper's place never nearer its goal line (a ball lying on the
                               -- line is walked into: an own goal)
    keeper_clear = 1.5,        -- m: a ball this near the own goal's centre: the goalkeeper clears it
                               -- (when it is first to it; the striker then waits upfield:)
    receive_ahead = 1.5,       -- m upfield of the ball ...
    receive_inside = 0.5,      -- ... at this fraction of the ball's y (towards the centre line)
    defender_gap = 1.0,        -- m short of the ball on the line from the own goal's centre to it
    defender_home = 1.5,       -- m in front of the own goal while no ball is known
    supporter_back = 1.0,      -- m behind the ball ...
    supporter_side = 1.2,      -- m ... and to the side, towards the centre line
    supporter_home = -1.0,     -- m: x while no ball is known
    field_margin = 0.4,        -- m kept inside the field lines
    arrive = 0.25,             -- m: at the position (then turn to the ball and stand)
    -- kick-off positions in READY (field x, y, heading) of the roles other than the striker's (which is
    -- behavior.lua's ready_pose); supporters by player number: even ones at y, odd ones at -y
    ready = { defender = { -3.0, 0.0, 0.0 }, supporter = { -2.0, 1.5, 0.0 }, goalkeeper = { -4.2, 0.0, 0.0 } },
  },
  -- the automatic referee in the simulator (Tools/match/referee.lua, a GameController: Tools/match/match.sh).
  -- Humanoid League KidSize numbers where the rules have one; s are simulated seconds.
  referee = {
    half_time = 300,           -- s of PLAYING per half (HL: 10 min; match.sh passes shorter ones)
    initial_time = 2,          -- s in INITIAL before READY (robots beside the touch line)
    ready_time = 45,           -- s in READY (HL: 45 s to reach the kick-off positions)
    set_time = 5,              -- s in SET before the kick-off whistle
    break_time = 5,            -- s of FINISHED at half time before the second half's INITIAL
    first_kickoff = 1,         -- team (1 or 2, in the teams' order) taking the first kick-off
    goalkeeper = 1,            -- player number flagged goalKeeper in both teams (0: none)
    packet_period = 0.5,       -- s between GameController packets (the GameController sends 2 per s)
    look_period = 0.1,         -- s between the referee's looks at the world
    penalty_time = 30,         -- s a penalized robot stays off the field (HL standard penalty)
    penalty_code = 34,         -- HL penalty: PICKUP_OR_INCAPABLE (fallen too long, left the field)
    fallen_time = 20,          -- s a robot may lie before it is incapable (HL: it must get up itself)
    outside = 0.3,             -- m the torso is beyond a line: the robot left the field
    off_field = 0.6,           -- m beyond the touch line a penalized robot waits
    start_x = 0.8,             -- m from the halfway line of the first robot beside the touch line ...
    start_spacing = 0.9,       -- m ... and between robots of a team
    touch = 0.35,              -- m: the robot nearest the ball, this near, touched it when ...
    touch_dv = 0.15,           -- m/s: ... the ball's velocity changed this much in a look (rolling: 0.06)
    setplay_prepare = 15,      -- s from a set play's call to the referee's execute
    setplay_execute = 10,      -- s after execute until normal play (or the ball moved)
    ball_moved = 0.2,          -- m the ball moves: a kick-off or set play is taken
    -- the fall census (Tools/match/census.lua): a fall's cause from the truth in the window before its tip
    census = {
      tip_angle = 0.3,         -- rad of torso tilt: the tip (under the walk's fallAngleRate, 0.35: the motion
                               -- state at the tip is the one the robot fell in, not `falling`)
      window = 1.0,            -- s before the tip in which a contact, the ball, a kick, a turn counts
      standup_after = 4.0,     -- s: a fall this soon after a stand-up or lying is a stand-up that failed
      goal = 0.25,             -- m from the torso to a goal's posts or nets: the robot touches the goal (half
                               -- the arms' 0.3 m across plus the post's radius, 0.05 m, and a margin)
      contact = 0.3,           -- m between two torsos: their arms touch side by side (OP3: the upper arms'
                               -- boxes reach 0.15 m beside the torso, shared/robots/op3_reference.txt)
      ball = 0.2,              -- m from the torso's ground point to the ball's centre: the ball at a foot (its
                               -- radius 0.07 m plus a foot's 0.13 m reach ahead of or beside the torso)
      turn_rate = 0.3,         -- rad/s commanded or measured: a turn
      side_speed = 0.05,       -- m/s commanded or measured sideways: a sideways step
      moving = 0.02,           -- m/s commanded or measured: walking, not standing in the walk
      history = 6.0,           -- s of looks kept per robot
    },
  },
}
