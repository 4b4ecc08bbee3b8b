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

# rr_build configures only when it must (a second scripts/run with nothing changed re-ran CMake's
# configure for half a minute), and rr_install_deps waits for the dpkg lock another apt-get holds
# (it failed at once): both with stand-ins for cmake, apt-get and dpkg-query that record their
# arguments.
fake=$work/fake
mkdir -p "$fake"
cat >"$fake/cmake" <<'SH'
#!/bin/bash
echo "cmake $*" >>"$FAKE_CALLS"
if [ "$1" = -S ]; then touch "$4/CMakeCache.txt" "$4/Makefile"; mkdir -p "$RR_DEVEL"; touch "$RR_DEVEL/setup.bash"; fi
SH
printf '#!/bin/bash
echo "apt-get $*" >>"$FAKE_CALLS"
' >"$fake/apt-get"
printf '#!/bin/bash
exit 1
' >"$fake/dpkg-query"  # nothing is installed
chmod +x "$fake"/*
configures() {  # configures BUILD_TYPE: rr_build's cmake calls, one "configure" or "build" each
  (export RR_DEVEL=$work/fake_devel RR_BUILD_TESTS=0 FAKE_CALLS=$work/calls PATH=$fake:$PATH
  : >"$work/calls"
  rr_build "$work/fake_build" "$1" >/dev/null 2>&1
  sed 's/^cmake -S .*/configure/; s/^cmake --build .*/build/' "$work/calls" | tr '\n' ' ')
}
calls=$(configures Release)
check "a first build configures ($calls)" [ "$calls" = "configure build " ]
calls=$(configures Release)
check "a second build with nothing changed does not ($calls)" [ "$calls" = "build " ]
calls=$(configures Debug)
check "another build type configures ($calls)" [ "$calls" = "configure build " ]
rm "$work/fake_build/Makefile"
calls=$(configures Debug)
check "a build directory without its Makefile configures ($calls)" [ "$calls" = "configure build " ]
if [ "$(id -u)" = 0 ]; then  # (with sudo, sudo's own PATH would find the real apt-get)
  /usr/bin/python3 -c 'import fcntl, sys, time
f = open(sys.argv[1], "w"); fcntl.lockf(f, fcntl.LOCK_EX); time.sleep(30)' "$work/dpkg_lock" &
  holder=$!
  started+=("$holder")
  sleep 0.5
  # shellcheck disable=SC2034  # rr_install_deps reads them
  (RR_ROOT=$work RR_PACKAGES=(no-such-package)
  export RR_DPKG_LOCK=$work/dpkg_lock FAKE_CALLS=$work/calls PATH=$fake:$PATH
  : >"$work/calls"
  rr_install_deps) >"$work/apt_out" 2>&1 || true
  check "apt-get waits for the dpkg lock" grep -q "apt-get -o DPkg::Lock::Timeout=600 install" \
    "$work/calls"
  check "... and says so when another holds it" grep -q "holds the dpkg lock: waiting" \
    "$work/apt_out"
  kill "$holder"
fi

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
grep -q "ready:" "$work/first" || cat "$work/first"  # why not
check "_seed:=3 reached roomba_fsm" [ "$(rosparam get /roomba_fsm/seed 2>/dev/null)" = 3 ]
# A second run is refused before it installs, configures or builds anything (issue 45: it used
# to rebuild for 40 s first): on this machine by the lock of the master's URI...
rc=0
(unset RR_NO_BUILD && timeout 30 "$run" fsm) >"$work/second" 2>&1 || rc=$?
check "a second scripts/run on the same master is refused (exit $rc)" [ "$rc" = 1 ]
check "... saying another one runs there" grep -q "another scripts/run is starting or running" \
  "$work/second"
check "... before building" bash -c "! grep -q 'building\|configuring' '$work/second'"
# ... and from another machine (another lock directory) by the master's list of nodes.
rc=0
(unset RR_NO_BUILD && TMPDIR=$work timeout 30 "$run" fsm) >"$work/second" 2>&1 || rc=$?
check "a second scripts/run from elsewhere is refused (exit $rc)" [ "$rc" = 1 ]
check "... saying which nodes run already" grep -q "already runs /roomba_sim /roomba_fsm" \
  "$work/second"
check "... before building" bash -c "! grep -q 'building\|configuring' '$work/second'"
check "... and the first one still runs" kill -0 "$first"
kill -TERM "$first"
wait "$first" 2>/dev/null || true
for _ in $(seq 100); do rosnode list 2>/dev/null | grep -q roomba_fsm || break; sleep 0.1; done

# Several robots in a map: placed on its free floor, each with its own state machine and lidar,
# and the simulator serves the map.
"$run" --world apartment --robots 2 fsm >"$work/map" 2>&1 &
map_run=$!
started+=("$map_run")
for _ in $(seq 300); do grep -q "ready:" "$work/map" && break; sleep 0.1; done
check "scripts/run --world apartment --robots 2 fsm is ready" grep -q "ready:" "$work/map"
check "... with robot1 and robot2 driving" bash -c \
  "rosnode list | grep -q /robot1/roomba_fsm && rosnode list | grep -q /robot2/roomba_fsm"
check "... and the apartment on /map" bash -c \
  "timeout 10 rostopic echo -n 1 /map/info/width | grep -q 210"
# Each robot's lidar under its namespace, in its own frame (the world's LDS preset).
for k in 1 2; do
  check "... robot$k's scan on /robot$k/scan in robot$k/base_scan" bash -c \
    "timeout 10 rostopic echo -n 1 /robot$k/scan/header/frame_id | grep -q robot$k/base_scan"
done
kill -TERM "$map_run"
wait "$map_run" 2>/dev/null || true
stop_master

# in_terminal COMMAND...: COMMAND as a terminal starts it, in its own process group with Ctrl-C
# not ignored (a script's background commands ignore it); a signal to the group is then what a
# terminal's Ctrl-C, or a service manager's stop, sends.
in_terminal() {
  exec /usr/bin/python3 -c 'import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_DFL)
os.setsid()
os.execvp(sys.argv[1], sys.argv[1:])' "$@"
}
leftovers() {  # the processes of this checkout's nodes or of the master on $port still running
  ps -eo pid,args | grep -v grep | grep -e "$RR_DEVEL/lib/roomba_rrt/" -e "roscore -p $port" \
    -e "rosmaster --core -p $port" || true
}
# Navigation in the apartment with the script's own roscore: the goal that 'ready:' suggests is
# on the apartment's free floor (it suggested (3.0, 4.55), outside the apartment, whatever the
# world), and a TERM to the whole process group stops everything quietly.
in_terminal "$run" --world apartment nav >"$work/nav" 2>&1 &
nav_run=$!
started+=("$nav_run")
for _ in $(seq 600); do grep -q "2D Nav Goal" "$work/nav" && break; sleep 0.1; done
check "scripts/run --world apartment nav is ready" grep -q "ready:" "$work/nav"
grep -q "ready:" "$work/nav" || cat "$work/nav"  # why not
goal=$(grep -o 'position: {x: [-0-9.]*, y: [-0-9.]*}' "$work/nav" | head -n 1 || true)
check "... suggesting a goal ($goal)" [ -n "$goal" ]
goal_x=$(echo "$goal" | sed 's/.*x: \([-0-9.]*\),.*/\1/')
goal_y=$(echo "$goal" | sed 's/.*y: \([-0-9.]*\)}.*/\1/')
# Its answer on stdout; rospy's log on stderr (actionlib may log about goals of other clients).
state=$(timeout 30 /usr/bin/python3 - "$goal_x" "$goal_y" 2>"$work/goal_log" <<'PY'
import sys, rospy, actionlib
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
rospy.init_node("suggested_goal")
client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
client.wait_for_server(rospy.Duration(20))
goal = MoveBaseGoal()
goal.target_pose.header.frame_id = "map"
goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = map(float, sys.argv[1:3])
goal.target_pose.pose.orientation.w = 1
client.send_goal(goal)
rospy.sleep(rospy.Duration(2.0))  # robot time: a refused goal is ABORTED at once
print("aborted: " + client.get_goal_status_text() if client.get_state() == GoalStatus.ABORTED
      else "taken")
client.cancel_all_goals()
PY
)
check "... which navigation takes ($state)" [ "$state" = taken ]
[ "$state" = taken ] || sed 's/^/    its log: /' "$work/goal_log"
kill -TERM -- "-$nav_run"
rc=0
wait "$nav_run" || rc=$?
check "a TERM to its process group stops it with exit 0 ($rc)" [ "$rc" = 0 ]
check "... without bash's pop_var_context errors" bash -c "! grep -q pop_var_context '$work/nav'"
sleep 1
check "... and nothing of it left running" [ -z "$(leftovers)" ]

# Its own roscore ending: said, and a non-zero exit (it exited 0 without a word).
in_terminal "$run" fsm >"$work/own" 2>&1 &
own_run=$!
started+=("$own_run")
for _ in $(seq 300); do grep -q "ready:" "$work/own" && break; sleep 0.1; done
check "scripts/run fsm with its own roscore is ready" grep -q "ready:" "$work/own"
grep -q "ready:" "$work/own" || cat "$work/own"  # why not
roscore_pid=$(pgrep -P "$own_run" roscore || true)
check "... its roscore found ($roscore_pid)" [ -n "$roscore_pid" ]
[ -n "$roscore_pid" ] && kill -INT "$roscore_pid"
rc=0
timeout 30 tail --pid="$own_run" -f /dev/null || true
wait "$own_run" || rc=$?
check "when that roscore ends it exits non-zero ($rc)" [ "$rc" = 1 ]
check "... saying so" grep -q "the roscore this script started ended" "$work/own"
sleep 1
check "... and nothing of it left running" [ -z "$(leftovers)" ]

# Ctrl-C during start-up: a quiet stop, no Python traceback, at whatever moment it comes.
for delay in 0.5 1.5 2.5; do
  in_terminal "$run" fsm >"$work/early" 2>&1 &
  early=$!
  started+=("$early")
  sleep "$delay"
  kill -INT -- "-$early" 2>/dev/null || true
  rc=0
  wait "$early" || rc=$?
  check "Ctrl-C $delay s into start-up: exit 0 ($rc)" [ "$rc" = 0 ]
  check "... without a traceback" bash -c "! grep -q 'Traceback\|pop_var_context' '$work/early'"
  grep -q 'Traceback\|pop_var_context' "$work/early" && cat "$work/early" # which one, and where
  # Within 20 s: beside a fresh-debian build, one stop took longer than 10 s to end everything.
  for _ in $(seq 200); do [ -z "$(leftovers)" ] && break; sleep 0.1; done
  check "... and nothing of it left running" [ -z "$(leftovers)" ]
  if [ -n "$(leftovers)" ]; then  # what, for whoever reads the log
    leftovers | sed 's/^/    left running: /'
    tail -n 5 "$work/early" | sed 's/^/    its output: /'
  fi
done
[ "$failures" = 0 ]
