-- The simulator's quick start: with no GameController, play 2 s after start-up
-- (Config/common/game.lua: a real robot waits in INITIAL for a packet or the button).
return {
  gamecontroller = { start_without = 'playing' },
}
