-- A site with today's ball (Tools/bench/white_score.sh): the sim's ball is the white one.
return {
  ball = { kind = 'white' },
}
