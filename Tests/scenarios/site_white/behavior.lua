-- A site with today's ball (Tools/bench/white_score.sh): team and player as Config/site's.
return {
  team_number = 1,
  player_number = 1,
}
