#!/usr/bin/env bash
# Issue 11, item 4: after a master restart the system heals. scripts/run (supervising) drives the
# robot with the FSM; the master is killed and started again on the same port, then roomba_sim is
# restarted (rosnode kill; the supervisor starts it again). The robot must drive again within 5 s
# of wall time after the simulator's restart. Needs built nodes (RR_DEVEL, default ./devel).
set -euo pipefail
# shellcheck source=ros_test_env.bash
source "$(dirname "$0")/ros_test_env.bash"
run=0
cleanup() {
  if [ "$run" -gt 0 ]; then kill -TERM "$run" 2>/dev/null && wait "$run" 2>/dev/null; fi
  cleanup_env
}
trap cleanup EXIT
say() { echo "[master_restart_test] $*"; }
wait_for_node() {  # wait_for_node NAME SECONDS: until the master lists the node
  local end=$((SECONDS + $2))
  while ((SECONDS < end)); do rosnode list 2>/dev/null | grep -qx "$1" && return 0; sleep 0.2; done
  say "FAIL: $1 is not registered after $2 s"; exit 1
}

start_master
RR_NO_BUILD=1 RR_NO_RVIZ=1 "$root/scripts/run" fsm >"$work/run.log" 2>&1 &
run=$!
wait_for_node /roomba_sim 30
wait_for_node /roomba_fsm 30
python3 "$here/odom_moving.py" --timeout 20 || { cat "$work/run.log"; exit 1; }
say "driving; restarting the master"

stop_master
start_master
t0=$(date +%s.%N)
wait_for_node /roomba_sim 15
wait_for_node /roomba_fsm 15
python3 "$here/odom_moving.py" --timeout 10 || { say "FAIL after the master restart"; cat "$work/run.log"; exit 1; }
say "driving again $(python3 -c "print(round($(date +%s.%N) - $t0, 1))") s after the new master"
grep -q "roomba_sim exited with code 75" "$work/run.log" || { say "FAIL: no restart logged"; cat "$work/run.log"; exit 1; }

say "restarting roomba_sim"
t0=$(date +%s.%N)
rosnode kill /roomba_sim >/dev/null
sleep 0.5
python3 "$here/odom_moving.py" --timeout 4.5 || { say "FAIL: not driving within 5 s of the simulator's restart"; cat "$work/run.log"; exit 1; }
elapsed=$(python3 -c "print(round($(date +%s.%N) - $t0, 1))")
say "driving again $elapsed s after roomba_sim was restarted"
python3 -c "import sys; sys.exit(0 if $elapsed <= 5.0 else 1)" || { say "FAIL: more than 5 s"; exit 1; }
say "PASS"
