-- A site with today's ball (Tests/bench/white_score.sh): the sim's ball is the white one.
return {
  ball = { kind = 'white' },
}
