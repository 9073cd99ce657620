-- What each body must reach in the walking scenarios (Tests/motion/sim_scenarios.lua): the command
-- given and the least measured speed, per robot (ROBOT). The OP3's figures are the platform's
-- reference; the DARwIn-OP's forward goal is >= 0.20 m/s for 30 s; the Hubo2+'s are forward
-- >= 0.25 m/s for 30 s, sideways 0.1 m/s, turning 0.5 rad/s; the HOAP-3's (8.8 kg on 3-4.5 N m
-- drives) forward >= 0.12 m/s, sideways and backwards 0.04 m/s, turning 0.4 rad/s.
return {
  op3 = {
    forward = { command = 0.35, least = 0.25 },   -- m/s
    sideways = { command = 0.12, least = 0.10 },  -- m/s
    backward = { command = 0.12, least = 0.10 },  -- m/s
    turn = { command = 2.2, least = 2.0 },        -- rad/s (the goal; 2.18-2.20 measured)
    kick = { least = 2.0 },                       -- m the ball travels
  },
  darwin = {
    forward = { command = 0.25, least = 0.20 },
    sideways = { command = 0.12, least = 0.10 },
    backward = { command = 0.12, least = 0.10 },
    turn = { command = 1.7, least = 1.0 },
    kick = { least = 1.2 },                       -- reaches 1.30-1.38 m (seeds 1-3)
  },
  hubo2plus = {
    forward = { command = 0.30, least = 0.25 },
    sideways = { command = 0.12, least = 0.10 },
    backward = { command = 0.12, least = 0.10 },
    turn = { command = 0.6, least = 0.5 },
    kick = { least = 0 },                         -- no kick target: not a football robot
  },
  hoap3 = {
    forward = { command = 0.14, least = 0.12 },
    sideways = { command = 0.05, least = 0.04 },
    backward = { command = 0.05, least = 0.04 },
    turn = { command = 0.5, least = 0.4 },
    kick = { least = 0 },                         -- no kick yet
  },
}
