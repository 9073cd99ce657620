-- The simulator: its quick start: with no GameController, play 2 s after start-up
-- (Config/common/game.lua: a real robot waits in INITIAL for a packet or the button).
return {
  -- the simulated robots and the test GameController live on this machine: listen on loopback only
  gamecontroller = { start_without = 'playing', interface = 'lo' },
  -- team messages stay on this machine (every simulated robot listens on it)
  team = { broadcast = '127.255.255.255', interface = 'lo' },
}
