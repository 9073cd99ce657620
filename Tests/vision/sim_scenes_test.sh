#!/usr/bin/env bash
# Ball detection over seeded sim scenes: dcm_sim in lockstep renders the head camera's view, the
# scene script (sim_scenes.lua) places robot and ball and runs the vision pipeline. TAP.
#   SCENES=N (default 90), SEED=N (default 1), SCENE_SCRIPT=another scene script (goal_scenes_test.sh)
set -u
cd "$(dirname "$0")/../.."
source Run/env.sh
[ -x build/bin/dcm_sim ] || { echo "not ok 1 - build/bin/dcm_sim not built"; exit 1; }
build/bin/dcm_sim --lockstep --seed 1 --quiet >/tmp/scenes_dcm.$$.log 2>&1 &
DCM=$!
cleanup() {
  kill "$DCM" 2>/dev/null; wait "$DCM" 2>/dev/null
  Tools/shm/shm remove >/dev/null 2>&1
  rm -f /tmp/scenes_dcm.$$.log
}
trap cleanup EXIT
# wait for the DCM to publish its first tick
for _ in $(seq 100); do
  luajit -e "os.exit(require('shm').open('sync').lockstep[0] == 1 and 0 or 1)" 2>/dev/null && break
  sleep 0.1
done
luajit "${SCENE_SCRIPT:-Tests/vision/sim_scenes.lua}" "${SCENES:-90}" "${SEED:-1}"
