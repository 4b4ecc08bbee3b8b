#!/usr/bin/env bash
# Issue 13: the nodes spread over two machines against one master. Two network namespaces stand
# in for two hosts, joined by a veth pair (a cable): "machine A" (10.77.0.1) runs roscore and
# roomba_sim, "machine B" (10.77.0.2) runs roomba_fsm and rrt_planner; each has only its loopback
# and its end of the cable, so every message between them crosses the link. Checked from B: the
# robot drives, bumps and recovers (roomba_fsm on B drives roomba_sim on A); from A: a
# `rosservice call /rrt_planner/plan_path` answers success (the planner on B).
#
#   sudo test/integration/two_machines_test.bash      # by hand, from the repository root
#
# Needs root, iproute2 (ip netns) and util-linux (nsenter); without them it prints why and exits
# 77, which ctest reports as skipped. Processes enter a namespace with `nsenter --net` rather than
# `ip netns exec`: the latter also remounts / and /sys, which fails in a chroot (CI's fresh Debian).
set -euo pipefail
# shellcheck source=ros_test_env.bash
source "$(dirname "$0")/ros_test_env.bash"
say() { echo "[two_machines_test] $*"; }
skip() {  # ctest: SKIP_RETURN_CODE 77
  say "SKIP: $*"
  exit 77
}

a=rr2m_a_$$ b=rr2m_b_$$  # the namespaces ("machines"), unique per run
ip_a=10.77.0.1 ip_b=10.77.0.2
master_uri=http://$ip_a:$port
made=()
# ip netns add bind-mounts /run/netns onto itself when it is not a mount point yet. In a chroot
# (CI's fresh Debian) that mount would outlive the test and keep the chroot from being removed:
# cleanup undoes it when this run made it and no other namespace is left in it.
netns_dir=/run/netns netns_was_mounted=0
if mountpoint -q "$netns_dir" 2>/dev/null; then netns_was_mounted=1; fi
cleanup() {
  local ns pids
  trap - EXIT
  for ns in "${made[@]}"; do  # every process on the "machine", then the machine
    pids=$(ip netns pids "$ns" 2>/dev/null || true)
    # shellcheck disable=SC2086
    if [ -n "$pids" ]; then kill -INT $pids 2>/dev/null || true; fi
  done
  ((${#made[@]})) && sleep 1
  for ns in "${made[@]}"; do
    pids=$(ip netns pids "$ns" 2>/dev/null || true)
    # shellcheck disable=SC2086
    if [ -n "$pids" ]; then kill -KILL $pids 2>/dev/null || true; fi
    ip netns delete "$ns" 2>/dev/null || true  # the veth pair goes with it
  done
  if [ "$netns_was_mounted" = 0 ] && mountpoint -q "$netns_dir" 2>/dev/null &&
    [ -z "$(ls -A "$netns_dir")" ]; then
    umount "$netns_dir" 2>/dev/null || true
  fi
  wait 2>/dev/null || true
  cleanup_env
}
trap cleanup EXIT

[ "$(id -u)" = 0 ] || skip "needs root to create network namespaces (run it with sudo)"
command -v ip >/dev/null || skip "needs ip (Debian package iproute2)"
command -v nsenter >/dev/null || skip "needs nsenter (Debian package util-linux)"

# on NS COMMAND...: COMMAND on "machine" NS (its network namespace), with that machine's ROS_IP.
on() {
  local ns=$1 addr=$ip_a
  shift
  [ "$ns" = "$b" ] && addr=$ip_b
  nsenter --net="/run/netns/$ns" env ROS_IP="$addr" ROS_MASTER_URI="$master_uri" "$@"
}

for ns in "$a" "$b"; do
  err=$(ip netns add "$ns" 2>&1) || skip "cannot create a network namespace (ip netns add: $err)"
  made+=("$ns")
done
err=$(nsenter --net="/run/netns/$a" ip link add veth0 type veth peer name veth1 netns "$b" 2>&1) ||
  skip "cannot create a veth pair between the namespaces ($err)"
on "$a" ip addr add "$ip_a/24" dev veth0
on "$b" ip addr add "$ip_b/24" dev veth1
for ns in "$a" "$b"; do
  on "$ns" ip link set lo up
done
on "$a" ip link set veth0 up
on "$b" ip link set veth1 up
say "machine A ($a): $(on "$a" ip -brief addr show veth0 | tr -s ' ')"
say "machine B ($b): $(on "$b" ip -brief addr show veth1 | tr -s ' ')"

# Machine A: the master and the simulator (10x real time; 0.4 m from the right wall, facing it,
# so roomba_fsm's first MoveForward bumps within a second of robot time).
on "$a" roscore -p "$port" >"$work/roscore.log" 2>&1 &
roscore_pid=$!
# Waits are deadlines in seconds, not counts of tries: under a full scripts/test (two cores, other
# tests starting masters and nodes) roscore can take tens of seconds to answer, and each try
# (a Python process) takes longer too; 150 tries once ran out before the master was up.
up=0
deadline=$((SECONDS + 90))
while ((SECONDS < deadline)); do
  if on "$b" bash -c "$(declare -f master_online); master_online"; then up=1 && break; fi
  kill -0 "$roscore_pid" 2>/dev/null || break  # roscore died: no use waiting
  sleep 0.2
done
if [ $up = 0 ]; then
  say "FAIL: the master on A is not reachable from B after $((SECONDS - deadline + 90)) s"
  cat "$work/roscore.log"
  exit 1
fi
say "the master on A answers B at $master_uri"
on "$a" rosparam set /use_sim_time true
on "$a" rosrun roomba_rrt roomba_sim _real_time_factor:=10 _initial_pose/x:=5.8 \
  >"$work/sim.log" 2>&1 &
# Machine B: the behaviour and the planner.
on "$b" rosrun roomba_rrt roomba_fsm _seed:=1 >"$work/fsm.log" 2>&1 &
on "$b" rosrun roomba_rrt rrt_planner >"$work/planner.log" 2>&1 &

show_logs() {
  local f
  for f in sim fsm planner; do echo "--- $f.log"; tail -n 20 "$work/$f.log"; done
}
if ! on "$b" python3 "$here/bump_recovery.py" --timeout 60; then
  say "FAIL: roomba_fsm on B does not drive roomba_sim on A"
  show_logs
  exit 1
fi
say "ok: roomba_fsm on B drives roomba_sim on A: it drives, bumps and recovers"

reply=""
deadline=$((SECONDS + 60))
while ((SECONDS < deadline)); do  # until rrt_planner on B has registered its service
  on "$a" rosservice list 2>/dev/null | grep -qx /rrt_planner/plan_path && break
  sleep 0.5
done
reply=$(on "$a" timeout 30 rosservice call /rrt_planner/plan_path "{scenario: 'a'}" 2>&1) || true
if ! grep -q '^success: True' <<<"$reply"; then
  say "FAIL: rosservice call /rrt_planner/plan_path from A did not answer success:"
  echo "$reply"
  show_logs
  exit 1
fi
summary=$(grep -E '^(success|length|iterations):' <<<"$reply" | tr '\n' ' ')
say "ok: rosservice call /rrt_planner/plan_path from A answered by B: $summary"
say "PASS"
