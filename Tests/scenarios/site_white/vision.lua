-- A site with today's ball (Tools/bench/white_score.sh): the vision looks for the white ball.
return {
  ball = { kind = 'white' },
}
