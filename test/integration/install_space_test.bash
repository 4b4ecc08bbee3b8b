#!/usr/bin/env bash
# The install space works on its own (issue 19 item 3, issue 22 item 1): the package installed
# with `cmake --install` into a scratch prefix, then, with only that prefix's setup.bash sourced
# (no devel space, no source tree on any path):
#   - every installed executable finds its libraries (ldd: nothing "not found");
#   - roomba_bt runs the lab's tree and the navigation tree against roomba_sim (commands on
#     /cmd_vel; the move_base action server up); roomba_nav_eval reaches its goals;
#   - reconfigure.test, installed with its test node, passes under rostest.
# Needs the built package (RR_BUILD, default ./build).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
export PATH=/usr/bin:/bin:$PATH
build=${RR_BUILD:-$root/build}
work=$(mktemp -d)
pids=()
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do timeout 10 tail --pid="$pid" -f /dev/null || kill -9 "$pid"; done
  rm -rf "$work"
}
trap cleanup EXIT
say() { echo "[install_space_test] $*"; }
fail() { say "FAIL: $*"; exit 1; }

# DESTDIR, not --prefix: catkin installs its setup files at the configured prefix whatever
# --prefix says. Below DESTDIR the whole install space lands together, and setup.bash finds its
# own folder, so it works moved as a user's install/ folder does.
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt")
DESTDIR="$work/root" cmake --install "$build" >"$work/install.log" 2>&1 ||
  { cat "$work/install.log"; fail "cmake --install"; }
ln -s "$work/root$prefix" "$work/install"

# A fresh environment: only the install space, as a user who sourced install/setup.bash. The
# command is exec'd all the way down, so a background one's pid is the command's own.
there() {  # there COMMAND...: the env -i ... bash -c ... command line for COMMAND
  there_cmd=(env -i HOME="$work" PATH=/usr/bin:/bin ROS_HOME="$work/ros" ROS_LOG_DIR="$work/log"
    ROS_MASTER_URI="$ROS_MASTER_URI" bash -c
    "set +u; source '$work/install/setup.bash'; set -u; exec $*")
}
run() { there "$@" && "${there_cmd[@]}"; }  # run COMMAND...: there, in the foreground
spawn() {  # spawn LOG COMMAND...: there, in the background; its pid in pids
  local log=$1
  shift
  there "$@"
  (exec "${there_cmd[@]}" >"$log" 2>&1) &
  pids+=($!)
}
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://localhost:$port

pkg=$(run rospack find roomba_rrt)
[ "$pkg" = "$work/install/share/roomba_rrt" ] || fail "rospack finds roomba_rrt at '$pkg'"
for exe in "$work"/install/lib/roomba_rrt/*; do
  [ -x "$exe" ] && [ -f "$exe" ] || continue
  case "$exe" in *.py) continue ;; esac
  if run ldd "$exe" | grep -q "not found"; then
    run ldd "$exe" | grep "not found"
    fail "$(basename "$exe") misses a library"
  fi
done
for exe in roomba_sim roomba_fsm roomba_bt rrt_planner coverage_planner roomba_teleop roomba_coverage \
  roomba_nav_eval rrt_monte_carlo rrt_plot; do
  [ -x "$work/install/lib/roomba_rrt/$exe" ] || fail "$exe is not installed"
done
say "ok: every executable installed, every library found"

spawn "$work/roscore.log" roscore -p "$port"
for _ in $(seq 100); do run rostopic list >/dev/null 2>&1 && break; sleep 0.2; done
spawn "$work/sim.log" rosrun roomba_rrt roomba_sim

nodes_command() {  # nodes_command NAME ARGS...: roomba_bt publishes /cmd_vel within 20 s
  local name=$1
  shift
  spawn "$work/$name.log" rosrun roomba_rrt roomba_bt "__name:=$name" "$@"
  if ! run timeout 20 rostopic echo -n 1 /cmd_vel >/dev/null 2>&1; then
    cat "$work/$name.log"
    fail "roomba_bt $* published no /cmd_vel from the install space"
  fi
}
nodes_command bt_lab
say "ok: roomba_bt with the lab's tree drives"
kill -TERM "${pids[-1]}" 2>/dev/null || true
timeout 10 tail --pid="${pids[-1]}" -f /dev/null || fail "roomba_bt did not stop on SIGTERM"
unset 'pids[-1]'
nodes_command bt_nav "_tree_file:=$pkg/config/roomba_nav_tree.xml" _planner:=in_process
run rostopic list | grep -qx /move_base/goal || fail "no move_base action server"
say "ok: roomba_bt with the navigation tree serves move_base"

out=$(run rosrun roomba_rrt roomba_nav_eval --goals 5 --seed 1 --json) || fail "roomba_nav_eval"
echo "$out" | grep -q '"reached_pct": 100.00' || fail "roomba_nav_eval: $out"
say "ok: roomba_nav_eval $out"

# rostest starts its own master on another port.
run rostest roomba_rrt reconfigure.test >"$work/rostest.log" 2>&1 ||
  { tail -n 40 "$work/rostest.log"; fail "rostest roomba_rrt reconfigure.test"; }
say "ok: rostest roomba_rrt reconfigure.test from the install space"
