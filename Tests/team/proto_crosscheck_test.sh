#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The team message against Google's protobuf: protoc (Debian) makes Python classes from the league's
# schema (Modules/teamcomm/robocup.proto); Python's protobuf (.venv) builds a message our decoder
# reads and reads one our encoder built (Tests/team/proto_crosscheck.py). TAP.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
GEN="$HRP_ROOT/build/gen/team_py"
mkdir -p "$GEN"
protoc --python_out="$GEN" -I Modules/teamcomm -I /usr/include Modules/teamcomm/robocup.proto || {
  echo "1..1"; echo "not ok 1 - protoc could not compile Modules/teamcomm/robocup.proto"; exit 1; }
exec python3 Tests/team/proto_crosscheck.py "$GEN"
