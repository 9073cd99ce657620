-- The world for the Hubo2+: ODE's QuickStep needs more iterations for a 45 kg robot whose light
-- links (0.1 kg neck, 0.3 kg hands) hang on 14 kg of torso: at 20 it jitters standing (torso
-- angular speed 0.06 rad/s, accelerometer off by 0.4 m/s^2 in Platforms/Sim's world test); at 40 it
-- stands as cleanly as the small bodies (0.04 rad/s, 9.81 m/s^2). A solver setting, not physics.
return {
  physics = {
    iterations = 40,             -- dWorldQuickStep iterations (20 for the small bodies)
  },
}
