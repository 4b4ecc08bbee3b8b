#!/usr/bin/env bash
# scripts/run as a newcomer uses it (issue 22, item 2): --help prints the usage and exits 0; a
# node that refuses its world file stops everything with a message naming it and a non-zero exit,
# never "ready:"; _param:= reaches the mode's node; a second scripts/run against a master that
# already runs these nodes is refused. Needs built nodes (RR_DEVEL, default ./devel).
set -euo pipefail
# shellcheck source=ros_test_env.bash
source "$(dirname "$0")/ros_test_env.bash"
trap cleanup_env EXIT
export RR_NO_BUILD=1 RR_NO_RVIZ=1
unset DISPLAY
run=$root/scripts/run
failures=0
say() { echo "[scripts_run_test] $*"; }
check() {  # check DESCRIPTION CONDITION...
  local what=$1
  shift
  if "$@"; then say "ok: $what"; else say "FAIL: $what"; failures=$((failures + 1)); fi
}

rc=0
"$run" --help >"$work/help" 2>&1 || rc=$?
check "--help exits 0 ($rc)" [ "$rc" = 0 ]
check "--help prints the usage with _param:=" grep -q "_param:=value" "$work/help"
rc=0
"$run" --no-such-option >/dev/null 2>&1 || rc=$?
check "an unknown option exits 2 ($rc)" [ "$rc" = 2 ]

# Stopping: a node that had a Ctrl-C but ignores it (one still starting, before ros::init sets
# roscpp's handler: a script's background commands start with INT ignored) gets TERM after 3 s,
# then KILL (rr_stop_child, which scripts/run's supervisors use). It hung scripts/run for ever
# when one node refused its world while another was starting. One that ends on INT ends at once.
# shellcheck source=../../scripts/lib/common.bash
source "$root/scripts/lib/common.bash"
stopped_within() {  # stopped_within SECONDS COMMAND...: COMMAND in the background, INT, stopped
  local limit=$1 pid start
  shift
  "$@" &
  pid=$!
  started+=("$pid")
  sleep 0.5
  start=$SECONDS
  kill -INT "$pid"
  rr_stop_child "$pid"
  ! rr_alive "$pid" && ((SECONDS - start <= limit))
}
check "a child ignoring INT and TERM is killed within 8 s" \
  stopped_within 8 bash -c "trap '' INT TERM; exec sleep 60"
check "a child ignoring INT is stopped by TERM within 5 s" \
  stopped_within 5 bash -c "trap '' INT; exec sleep 60"
check "a child that ends on INT is stopped within 1 s" \
  stopped_within 1 /usr/bin/python3 -c \
  "import signal, sys, time; signal.signal(signal.SIGINT, lambda *a: sys.exit(0)); time.sleep(60)"

start_master
printf 'robot:\n  radious: 0.2\n' >"$work/bad_world.yaml"
rc=0
timeout 60 "$run" fsm --world "$work/bad_world.yaml" >"$work/bad" 2>&1 || rc=$?
check "a world file roomba_sim refuses: exit 1 ($rc)" [ "$rc" = 1 ]
check "... naming roomba_sim" grep -q "/roomba_sim refused its parameters or world file" "$work/bad"
check "... never 'ready:'" bash -c "! grep -q 'ready:' '$work/bad'"
check "... and stopping the nodes it started" bash -c "! rosnode list 2>/dev/null | grep -q roomba_fsm"

"$run" fsm _seed:=3 >"$work/first" 2>&1 &
first=$!
started+=("$first")
for _ in $(seq 300); do grep -q "ready:" "$work/first" && break; sleep 0.1; done
check "scripts/run fsm _seed:=3 is ready" grep -q "ready:" "$work/first"
check "_seed:=3 reached roomba_fsm" [ "$(rosparam get /roomba_fsm/seed 2>/dev/null)" = 3 ]
rc=0
timeout 30 "$run" fsm >"$work/second" 2>&1 || rc=$?
check "a second scripts/run on the same master is refused (exit $rc)" [ "$rc" = 1 ]
check "... saying which nodes run already" grep -q "already runs /roomba_sim /roomba_fsm" \
  "$work/second"
check "... and the first one still runs" kill -0 "$first"
kill -TERM "$first"
wait "$first" 2>/dev/null || true
for _ in $(seq 100); do rosnode list 2>/dev/null | grep -q roomba_fsm || break; sleep 0.1; done

# Several robots in a map: placed on its free floor, each with its own state machine, and the
# simulator serves the map.
"$run" --world apartment --robots 2 fsm >"$work/map" 2>&1 &
map_run=$!
started+=("$map_run")
for _ in $(seq 300); do grep -q "ready:" "$work/map" && break; sleep 0.1; done
check "scripts/run --world apartment --robots 2 fsm is ready" grep -q "ready:" "$work/map"
check "... with robot1 and robot2 driving" bash -c \
  "rosnode list | grep -q /robot1/roomba_fsm && rosnode list | grep -q /robot2/roomba_fsm"
check "... and the apartment on /map" bash -c \
  "timeout 10 rostopic echo -n 1 /map/info/width | grep -q 210"
kill -TERM "$map_run"
wait "$map_run" 2>/dev/null || true
[ "$failures" = 0 ]
