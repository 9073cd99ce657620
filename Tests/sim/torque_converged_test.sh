#!/usr/bin/env bash
# Torque mode on the Hubo2+'s arm (Tests/sim/torque_mode_test.sh) with ODE's QuickStep at 400
# iterations instead of the body's 40: a solver setting, to show the figures do not hang on the
# body's iterations (the drift 0.1 mm at 40 and at 400 since the gear friction holds its place;
# about 50 s on 2 cores; make test).
exec "$(dirname "$0")/torque_mode_test.sh" 400
