#!/usr/bin/env bash
# roomba_teleop driving roomba_sim from a (pseudo-)terminal: keys, limits, bumper display, and a
# stop when the terminal goes away (teleop_drive.py does the typing and the checks).
set -euo pipefail
# shellcheck source=ros_test_env.bash
source "$(dirname "$0")/ros_test_env.bash"
trap cleanup_env EXIT
start_master
rosrun roomba_rrt roomba_sim >"$work/sim.log" 2>&1 &
started+=($!)
python3 "$here/teleop_drive.py"
