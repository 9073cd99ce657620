-- The venue's settings for this robot (the site layer: Config/site/, or the folder $HRP_SITE names).
-- Only keys the lower layers have may be set here; an unknown key is an error naming this file.
return {
  team_number = 1,              -- as the GameController knows the team
  player_number = 1,            -- 1..6 within the team
}
