# Sourced by the integration test scripts: the built package on the ROS paths (RR_DEVEL, default
# ./devel), a scratch directory $work (logs, ROS_HOME; removed at exit by cleanup_env), a free
# master port in ROS_MASTER_URI, start_master (a roscore on that port, pid in $master) and
# started (pids that cleanup_env stops).
here=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
root=$(cd "$here/../.." && pwd)
export PATH=/usr/bin:/bin:$PATH
export RR_DEVEL=${RR_DEVEL:-$root/devel}
# shellcheck source=../../scripts/lib/common.bash
source "$(dirname "${BASH_SOURCE[0]}")/../../scripts/lib/common.bash"  # rr_stop, rr_stop_child
set +u
# shellcheck disable=SC1091
source "$RR_DEVEL/setup.bash"
set -u
work=$(mktemp -d)
export ROS_LOG_DIR=$work/log ROS_HOME=$work
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://localhost:$port
master=0
master_online() { python3 -c 'import rosgraph,sys; sys.exit(0 if rosgraph.is_master_online() else 1)'; }
start_master() {
  roscore -p "$port" >>"$work/roscore.log" 2>&1 &
  master=$!
  for _ in $(seq 100); do master_online && return 0; sleep 0.1; done
  echo "roscore did not start" >&2
  exit 1
}
stop_master() {
  if [ "$master" -gt 0 ]; then rr_stop "$master"; fi
  master=0
}
# Background processes a test started (append their pids): cleanup_env interrupts them first.
started=()
cleanup_env() {
  ((${#started[@]})) && rr_stop "${started[@]}"
  stop_master
  rm -rf "$work"
}
