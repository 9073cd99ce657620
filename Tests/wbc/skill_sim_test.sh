#!/usr/bin/env bash
# tier: check (make check runs it: about 10 s)
# A whole-body skill in the sim (lockstep): the Hubo2+ runs hello_bye (Tests/wbc/hubo_hello_bye.lua,
# the skill Config/robots/hubo2plus/wbc_skills/hello_bye.lua) through Tests/wbc/wbc_sim_test.sh.
exec bash "$(dirname "$0")/wbc_sim_test.sh" hubo_hello_bye
