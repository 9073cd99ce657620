#!/usr/bin/env bash
# The 10-minute soak (make test; about a minute of wall time in lockstep): Tests/soak/soak.sh 600.
exec "$(dirname "$0")/soak.sh" 600
