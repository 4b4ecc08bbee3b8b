#!/usr/bin/env bash
# Issue 44, item 7: every executable of the package (nodes, tools, benchmarks and probes that are
# built) answers --help with its usage on stdout and exit code 0, at once and without a master
# (a node must not wait for one); map_comparison refuses a maps folder that is not there with a
# message (it died of an uncaught filesystem_error).
set -uo pipefail
bin=${RR_DEVEL:?RR_DEVEL is the devel space}/lib/roomba_rrt
export ROS_MASTER_URI=http://127.0.0.1:9  # nothing listens: a node that waited would time out
failures=0 checked=0
say() { echo "[help_test] $*"; }
for node in rrt_planner roomba_sim roomba_mapper roomba_map_saver coverage_planner roomba_fsm roomba_bt roomba_teleop rrt_plot \
  rrt_monte_carlo roomba_coverage roomba_nav_eval; do
  [ -x "$bin/$node" ] || { say "FAIL: $node is not built"; failures=$((failures + 1)); }
done
for exe in "$bin"/*; do
  name=$(basename "$exe")
  # Test executables (gtests, rostest nodes) and fuzzers are not a user's commands.
  [[ -f $exe && -x $exe && $name != *_test && $name != *_rostest && $name != *_fuzzer ]] || continue
  rc=0
  out=$(timeout 10 "$exe" --help </dev/null 2>/dev/null) || rc=$?
  checked=$((checked + 1))
  if [ "$rc" = 0 ] && [ -n "$out" ]; then
    say "ok: $name --help: $(head -1 <<<"$out" | cut -c1-80)"
  else
    say "FAIL: $name --help exited $rc with ${#out} bytes on stdout"; failures=$((failures + 1))
  fi
done
if [ -x "$bin/map_comparison" ]; then
  rc=0
  err=$(timeout 10 "$bin/map_comparison" --maps /nonexistent/maps 2>&1 >/dev/null) || rc=$?
  if [ "$rc" = 2 ] && grep -qF "map_comparison: --maps: '/nonexistent/maps' is not a directory" <<<"$err"; then
    say "ok: map_comparison refuses a missing maps folder"
  else
    say "FAIL: map_comparison --maps /nonexistent/maps: exit $rc, '$err'"; failures=$((failures + 1))
  fi
fi
[ "$failures" = 0 ] && say "PASS ($checked executables)" || { say "$failures failures"; exit 1; }
