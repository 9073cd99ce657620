-- The game's state machine: follows the GameController (or the start-up default) and penalties.
return {
  states = { 'initial', 'ready', 'set', 'playing', 'finished', 'penalized' },
  initial = 'initial',
  transitions = {
    ['*'] = { initial = 'initial', ready = 'ready', set = 'set', playing = 'playing',
      finished = 'finished', penalized = 'penalized' },
  },
}
