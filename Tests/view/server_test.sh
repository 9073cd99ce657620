#!/usr/bin/env bash
# tier: check (make check runs it: a few seconds)
# The live view's server without a browser (TAP, Tests/view/server_check.py): blocks written by a
# process reach an event stream, only changed blocks are sent, the client limit, bad options and a
# port in use are refused with a message naming them.
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
trap 'Tools/shm/shm remove >/dev/null 2>&1' EXIT
Tools/shm/shm remove >/dev/null 2>&1
python3 Tests/view/server_check.py
