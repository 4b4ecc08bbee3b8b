#!/usr/bin/env bash
# Issue 11, item 6: node parameters outside their ranges stop the node at start (exit 1) with a
# message naming the parameter; a node stops within 1 s of Ctrl-C, roomba_sim also at
# real_time_factor 1e-4 (where one step lasts 166 s of wall time) and still answers ~reset there,
# rrt_planner also while it is planning.
set -euo pipefail
# shellcheck source=ros_test_env.bash
source "$(dirname "$0")/ros_test_env.bash"
trap cleanup_env EXIT
start_master
rosparam set /use_sim_time true
failures=0
say() { echo "[node_parameters_test] $*"; }

refuses() {  # refuses TEXT NODE ARGS...: exits 1 within 20 s, its output contains TEXT
  local text=$1 rc=0
  shift
  rosparam delete "/$1" 2>/dev/null || true  # rosrun's _name:= values stay on the master
  timeout 20 rosrun roomba_rrt "$@" >"$work/out" 2>&1 || rc=$?
  if [ "$rc" = 1 ] && grep -qF -- "$text" "$work/out"; then
    say "ok: $* -> exit 1, '$text'"
  else
    say "FAIL: $* -> exit $rc, wanted 1 and '$text':"; cat "$work/out"; failures=$((failures + 1))
  fi
}
refuses "real_time_factor: must be in [0.0001, 10000], got 1e-300" roomba_sim _real_time_factor:=1e-300
refuses "real_time_factor" roomba_sim _real_time_factor:=1e9
refuses "step: must be in [0.0001, 1], got 1e-300" roomba_sim _step:=1e-300
refuses "coverage_cell_size" roomba_sim _coverage_cell_size:=1e-9
refuses "room.width" roomba_sim _room/width:=1e5
refuses "not a regular file" roomba_sim _world_file:=/tmp
refuses "~rate: must be in [1, 1000] Hz, got 1e+09" roomba_fsm _rate:=1e9
refuses "~rate: must be in [1, 1000] Hz, got 1e-300" roomba_bt _rate:=1e-300
refuses "~bumper_timeout" roomba_fsm _bumper_timeout:=1e300
refuses "~pose_latency: must be in [0, 1] s, got 5" roomba_bt _pose_latency:=5 \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
refuses "~planner must be 'in_process' with ~unknown" roomba_bt _unknown:=true _planner:=service \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
refuses "~transform_timeout: must be in [0, 10] s, got -1" roomba_bt _unknown:=true \
  _transform_timeout:=-1 _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
refuses "~log_file: cannot record with ~unknown" roomba_bt _unknown:=true \
  _log_file:=/tmp/unknown.btlog \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
# A stale map of the home (~known_map): a missing file, a NaN in it, or without ~unknown.
refuses "~known_map: /tmp/no_such_map.yaml" roomba_bt _unknown:=true \
  _known_map:=/tmp/no_such_map.yaml \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
printf 'image: %s\nresolution: .nan\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' \
  "$(rospack find roomba_rrt)/config/maps/furnished_walls.pgm" >"$work/nan_map.yaml"
refuses "~known_map: $work/nan_map.yaml: resolution" roomba_bt _unknown:=true \
  _known_map:="$work/nan_map.yaml" \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
refuses "~known_map is the map a robot that does not know the world is given" roomba_bt \
  _known_map:="$(rospack find roomba_rrt)/config/maps/furnished_walls.yaml" \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml"
refuses "~animate_rate: must be in [0.1, 1000] Hz" rrt_planner _animate_rate:=1e-300
refuses "~threads: must be in [1, 64]" rrt_planner _threads:=0
refuses "~max_marker_nodes: must be in [0, 5000000]" rrt_planner _max_marker_nodes:=-1
refuses "~plan_resolution: must be in [0, 10] m, got -1" rrt_planner _plan_resolution:=-1
refuses "~clearance: must be in [0, 0.17] m, got -1" coverage_planner _clearance:=-1
refuses "~robot_radius: must be in [0.001, 10] m, got 0" coverage_planner _robot_radius:=0
refuses "not a regular file" coverage_planner _world_file:=/tmp

# Issue 22, item 3: a value of the wrong type is refused naming the parameter (never the default).
refuses "~rate: must be a number, got 'fast' (a string)" roomba_fsm _rate:=fast
refuses "~seed: must be an integer, got 'abc' (a string)" roomba_bt _seed:=abc
refuses "~groot_port must be 0 (off) or a TCP port in 1..65534, got 70000" roomba_bt _groot_port:=70000
refuses "~real_time_factor: must be a number, got 'fast' (a string)" roomba_sim _real_time_factor:=fast
refuses "~step: must be a number, got 'big' (a string)" rrt_planner _step:=big
refuses "~max_linear_speed: must be a number, got 'x' (a string)" roomba_teleop _max_linear_speed:=x

# An unknown private parameter is warned about, with the nearest known name; the values in force
# are on the master while the node runs (rosparam get) and gone after it stops, unless the user
# set them: after SIGINT, and after SIGTERM (signal=TERM; issue 44: a node killed by it exited
# 143 and left them, read by the next start as the user's).
warns_and_writes_back() {  # NODE PARAMS...: runs NODE for 3 s, then sends it SIG${signal:-INT}
  local node=$1
  shift
  rosparam delete "/$node" 2>/dev/null || true
  rosrun roomba_rrt "$node" "$@" >"$work/out" 2>&1 &
  local pid=$!
  for _ in $(seq 50); do rosparam get "/$node/$probe" >/dev/null 2>&1 && break; sleep 0.1; done
  local value
  value=$(rosparam get "/$node/$probe" 2>/dev/null || echo unset)
  local sig=${signal:-INT} rc=0
  kill -"$sig" "$pid"
  wait "$pid" || rc=$?
  if [ "$rc" -ge 128 ]; then
    say "FAIL: $node died of SIG$sig (exit $rc) instead of stopping"; failures=$((failures + 1))
  fi
  if [ "$value" = "$expected" ]; then
    say "ok: $node shows ~$probe = $value while running"
  else
    say "FAIL: $node: rosparam get /$node/$probe gave '$value', wanted '$expected'"
    failures=$((failures + 1))
  fi
  if rosparam get "/$node/$probe" >/dev/null 2>&1; then
    say "FAIL: $node left ~$probe on the master"; failures=$((failures + 1))
  else
    say "ok: $node removed ~$probe when it stopped"
  fi
  # Nor the group it was in, emptied (~room: {} reads as given: a world with named robots then
  # refused the ~initial_pose nobody set).
  if [[ $probe == */* ]] && rosparam get "/$node/${probe%%/*}" >/dev/null 2>&1; then
    say "FAIL: $node left the empty group ~${probe%%/*} on the master"; failures=$((failures + 1))
  fi
  if grep -qF "$warning" "$work/out"; then
    say "ok: $node warns '$warning'"
  else
    say "FAIL: $node does not warn '$warning':"; cat "$work/out"; failures=$((failures + 1))
  fi
}
probe=room/width expected=6.4 warning="~real_time_factr is not a parameter of this node (did you mean ~real_time_factor?)" \
  warns_and_writes_back roomba_sim _real_time_factr:=2
probe=rate expected=60.0 warning="~sed is not a parameter of this node (did you mean ~seed?)" \
  warns_and_writes_back roomba_fsm _sed:=3
probe=goal_bias expected=0.1 warning="~stepp is not a parameter of this node (did you mean ~step?)" \
  warns_and_writes_back rrt_planner _stepp:=0.3
probe=clearance expected=0.01 warning="~clearence is not a parameter of this node (did you mean ~clearance?)" \
  warns_and_writes_back coverage_planner _clearence:=0.02
probe=room/width expected=6.4 warning="~real_time_factr" signal=TERM \
  warns_and_writes_back roomba_sim _real_time_factr:=2
probe=rate expected=60.0 warning="~sed" signal=TERM warns_and_writes_back roomba_fsm _sed:=3
probe=rate expected=60.0 warning="~sed" signal=TERM warns_and_writes_back roomba_bt _sed:=3
probe=goal_bias expected=0.1 warning="~stepp" signal=TERM warns_and_writes_back rrt_planner _stepp:=0.3
probe=clearance expected=0.01 warning="~clearence" signal=TERM \
  warns_and_writes_back coverage_planner _clearence:=0.02

# A map whose initial pose is a wall (a map's (0, 0) often is): roomba_sim refuses it, but
# roomba_bt and rrt_planner take the pose from tf and requests, and run (scripts/run --pose gives
# the pose to roomba_sim alone).
runs() {  # runs NODE ARGS...: still running after 3 s
  rosparam delete "/$1" 2>/dev/null || true
  rosrun roomba_rrt "$@" >"$work/out" 2>&1 &
  local pid=$!
  sleep 3
  if kill -0 "$pid" 2>/dev/null; then
    say "ok: $* runs"; kill -INT "$pid"; wait "$pid" || true
  else
    say "FAIL: $* stopped:"; cat "$work/out"; failures=$((failures + 1))
  fi
}
printf 'map: %s\ninitial_pose: {x: -5.2, y: -3.7}\n' \
  "$(rospack find roomba_rrt)/config/maps/apartment.yaml" >"$work/wall_start.yaml"
refuses "initial_pose: (-5.2, -3.7) puts the robot's disc inside a wall" roomba_sim \
  _world_file:="$work/wall_start.yaml"
runs roomba_bt _world_file:="$work/wall_start.yaml" \
  _tree_file:="$(rospack find roomba_rrt)/config/roomba_coverage_tree.xml" _planner:=in_process
runs rrt_planner _world_file:="$work/wall_start.yaml"

stops_quickly() {  # stops_quickly NODE ARGS...: after 3 s running, SIGINT ends it within 1 s
  rosparam delete "/$1" 2>/dev/null || true
  rosrun roomba_rrt "$@" >"$work/out" 2>&1 &
  local pid=$! t0 elapsed
  sleep 3
  if [ "$1" = rrt_planner ]; then  # a plan of minutes in progress must not hold up Ctrl-C
    timeout 10 rosservice call /rrt_planner/plan_path \
      "{scenario: 'a', algorithm: 'rrt_star', max_iterations: 5000000}" >/dev/null 2>&1 &
    sleep 1
  fi
  if [ "$1" = coverage_planner ]; then  # likewise a whole building's coverage plan (seconds)
    timeout 20 rosservice call /coverage_planner/plan_coverage "{start: {x: -12.0, y: 0.1}}" \
      >/dev/null 2>&1 &
    sleep 1
  fi
  if [ "$1" = roomba_sim ] && ! timeout 5 rosservice call /roomba_sim/reset >/dev/null; then
    say "FAIL: $* does not answer ~reset"; failures=$((failures + 1))
  fi
  t0=$(date +%s.%N)
  kill -INT "$pid"
  wait "$pid" || true
  elapsed=$(python3 -c "print(round($(date +%s.%N) - $t0, 2))")
  if python3 -c "import sys; sys.exit(0 if $elapsed < 1.0 else 1)"; then
    say "ok: $* stopped $elapsed s after SIGINT"
  else
    say "FAIL: $* took $elapsed s to stop after SIGINT"; failures=$((failures + 1))
  fi
}
# Issue 45, item 9: roomba_sim's start-up lines give the pose in force: --pose (as
# _initial_pose/x, /y) in a map whose file sets none is not reported as the default (0, 0).
says() {  # says TEXT NODE PARAMS...: NODE's output within its first 3 s contains TEXT
  local text=$1
  shift
  rosparam delete "/$1" 2>/dev/null || true
  ROSCONSOLE_STDOUT_LINE_BUFFERED=1 timeout -s INT 3 rosrun roomba_rrt "$@" >"$work/out" 2>&1 ||
    true
  if grep -qF -- "$text" "$work/out"; then
    say "ok: $* says '$text'"
  else
    say "FAIL: $* did not say '$text':"; cat "$work/out"; failures=$((failures + 1))
  fi
}
apartment=$root/config/maps/apartment.yaml
says "1 robot at (-3.8, 2.2) heading 0 rad" roomba_sim _world_file:="$apartment" \
  _initial_pose/x:=-3.8 _initial_pose/y:=2.2
if grep -q "initial_pose.x 0" "$work/out"; then
  say "FAIL: the pose given is reported as the default"; failures=$((failures + 1))
fi
says "sets no furniture, robot, initial_pose: the defaults are used" roomba_sim \
  _world_file:="$apartment"

stops_quickly roomba_sim _real_time_factor:=1e-4
stops_quickly roomba_sim _real_time_factor:=100
stops_quickly roomba_fsm _rate:=1000
stops_quickly rrt_planner
willow=$root/../shared/maps/willow_full.yaml  # planned in 6 s; the package's own worlds in ms
if [ -f "$willow" ]; then
  stops_quickly coverage_planner _world_file:="$willow"
else
  stops_quickly coverage_planner
fi
[ "$failures" = 0 ] && say PASS || { say "$failures failures"; exit 1; }
