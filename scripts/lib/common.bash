# Shared set-up for scripts/run, scripts/test, scripts/bench and scripts/figures.
# Source it; it defines functions only. Works on a fresh Debian 12 machine (as root, or with sudo).

# Debian's ROS needs Debian's Python (the one that has catkin_pkg), whatever else is on PATH.
export PATH=/usr/bin:/bin:$PATH

RR_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

# Every Debian package the project builds, runs, tests, fuzzes and benchmarks with, and every
# command the README tells users to run. Debian splits ROS messages in three: the C++ headers
# (lib*-msgs-dev), the Python classes (python3-*-msgs) and the .msg/.srv definitions
# (ros-*-msgs) that message generation reads; all three are listed for every message package.
RR_PACKAGES=(
  # toolchain
  build-essential cmake pkg-config git
  # ROS 1 core: catkin, roscpp, message generation, the master and the command-line tools
  catkin libroscpp-dev libroslib-dev ros-message-generation ros-message-runtime
  ros-core rosbash python3-roslaunch python3-rosnode python3-rosservice python3-rostopic
  python3-rosgraph python3-rosparam python3-rosmsg python3-rosbag python3-genpy python3-genmsg
  python3-yaml  # the documentation test reads PlanPath requests
  # messages this package uses or depends on: definitions, C++ headers, Python classes
  ros-std-msgs libstd-msgs-dev python3-std-msgs
  ros-std-srvs libstd-srvs-dev python3-std-srvs
  ros-geometry-msgs libgeometry-msgs-dev python3-geometry-msgs
  ros-nav-msgs libnav-msgs-dev python3-nav-msgs
  ros-visualization-msgs libvisualization-msgs-dev python3-visualization-msgs
  ros-rosgraph-msgs libros-rosgraph-msgs-dev python3-rosgraph-msgs
  ros-actionlib-msgs libactionlib-msgs-dev python3-actionlib-msgs
  ros-tf2-msgs libtf2-msgs-dev python3-tf2-msgs
  ros-roscpp-msg python3-roscpp-msg
  ros-move-base-msgs libmove-base-msgs-dev python3-move-base-msgs
  ros-sensor-msgs libsensor-msgs-dev python3-sensor-msgs  # roomba_sim's LaserScan
  # tf2 (C++ and Python) and its tools (tf2_echo, view_frames), actionlib (C++ and Python)
  libtf2-dev libtf2-ros-dev python3-tf2-ros tf2-tools
  libactionlib-dev python3-actionlib python3-actionlib-tools
  # dynamic_reconfigure: cfg generator, C++ server and its messages; Python client and dynparam
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  # libraries of the ROS-free cores and the tools
  libyaml-cpp-dev libcairo2-dev libtinyxml2-dev
  libpng-dev  # map images: PNG through libpng, netpbm read by hand, as map_server decodes them
  libzmq3-dev cppzmq-dev  # roomba_bt's Groot2 monitor (ZeroMQ, as BehaviorTree.CPP's)
  # tests, benchmarks, fuzzing (clang's libFuzzer and sanitizer runtimes), pictures
  libgtest-dev librostest-dev python3-rostest python3-rosunit
  python3-zmq  # the Groot2 protocol's test client
  libompl-dev libbenchmark-dev
  clang libfuzzer-14-dev libclang-rt-14-dev
  rviz xvfb libgl1-mesa-dri imagemagick iproute2 util-linux procps
)

rr_log() { printf '\033[1m[roomba_rrt]\033[0m %s\n' "$*" >&2; }

# Install whatever Debian packages are missing (nothing to do, and no network, when all are there).
# apt-get's output goes to build/apt.log; the terminal gets one line.
rr_install_deps() {
  local missing=() p
  for p in "${RR_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo="" log="$RR_ROOT/build/apt.log" t0=$SECONDS
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  mkdir -p "$RR_ROOT/build"
  rr_log "installing ${#missing[@]} missing Debian packages (with what they pull in; a few minutes on a fresh machine; log: ${log#"$RR_ROOT"/})"
  # Another apt-get (unattended-upgrades on a fresh machine at boot) may hold dpkg's lock: wait
  # for it instead of failing at once.
  if rr_dpkg_locked; then
    rr_log "another apt-get or unattended-upgrades holds the dpkg lock: waiting for it (up to $((RR_APT_LOCK_WAIT / 60)) min)"
  fi
  local wait_lock=(-o "DPkg::Lock::Timeout=$RR_APT_LOCK_WAIT")
  if ! { $sudo env DEBIAN_FRONTEND=noninteractive apt-get "${wait_lock[@]}" update -qq &&
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get "${wait_lock[@]}" install -y -q \
      "${missing[@]}"; } >"$log" 2>&1; then
    tail -n 30 "$log" >&2
    rr_log "apt-get failed; the whole output is in $log"
    return 1
  fi
  rr_log "installed in $((SECONDS - t0)) s"
  RR_INSTALLED=1  # rr_build configures again: find_package may find what was missing
}

# Seconds apt-get waits for dpkg's lock held by another apt-get.
RR_APT_LOCK_WAIT=${RR_APT_LOCK_WAIT:-600}

# rr_dpkg_locked: another process holds dpkg's front-end lock (a read-only probe of its fcntl
# lock, as apt takes it; false when the lock file is absent or cannot be read).
rr_dpkg_locked() {
  /usr/bin/python3 - "${RR_DPKG_LOCK:-/var/lib/dpkg/lock-frontend}" 2>/dev/null <<'PY'
import fcntl, struct, sys
try:
    f = open(sys.argv[1], "rb")
except OSError:
    sys.exit(1)
# F_GETLK: who would block a write lock on the whole file (apt's lock is a write lock).
probe = struct.pack("hhqqi", fcntl.F_WRLCK, 0, 0, 0, 0)
sys.exit(0 if struct.unpack("hhqqi", fcntl.fcntl(f, fcntl.F_GETLK, probe))[0] != fcntl.F_UNLCK
         else 1)
PY
}

# rr_run_logged LOG DESCRIPTION COMMAND...: run a build command with its output in LOG; on a
# terminal show one line that follows cmake's "[ NN%]" progress, elsewhere one line at the start.
# On failure print the errors (and the log's path) and return non-zero.
rr_run_logged() {
  local log=$1 what=$2 pid rc pct=""
  shift 2
  # In a process group of its own (setsid), in RR_LOGGED_PID while it runs: a script stopped
  # meanwhile stops the whole build (kill -TERM -- -$RR_LOGGED_PID) instead of leaving it running.
  setsid "$@" >"$log" 2>&1 &
  pid=$!
  # shellcheck disable=SC2034  # read by scripts/run's cleanup
  RR_LOGGED_PID=$pid
  if [ -t 2 ]; then
    while kill -0 "$pid" 2>/dev/null; do
      pct=$(grep -o '^\[ *[0-9]*%\]' "$log" 2>/dev/null | tail -n 1 | tr -d '[] ')
      printf '\r\033[1m[roomba_rrt]\033[0m %s %s ' "$what" "${pct:-...}" >&2
      sleep 1
    done
    printf '\r\033[K' >&2
  else
    rr_log "$what (log: ${log#"$RR_ROOT"/})"
  fi
  rc=0
  wait "$pid" || rc=$?
  # shellcheck disable=SC2034
  RR_LOGGED_PID=
  if [ $rc -ne 0 ]; then
    grep -E -B2 -A8 'error|Error|ERROR' "$log" | head -n 80 >&2 || tail -n 40 "$log" >&2
    rr_log "$what failed; the whole output is in $log"
  fi
  return $rc
}

# rr_build [BUILD_DIR] [BUILD_TYPE]: configure and build the package; sets RR_BUILD and RR_DEVEL.
# The catkin devel space (nodes, tools, setup.bash) goes to devel/ beside build/, not inside it:
# rosrun ignores every executable below <package>/build/, and the package is the repository root.
# RR_BUILD_TESTS=0 skips the test executables. Output goes to build/build.log. CMake's configure
# (half a minute) runs only when the build directory was not configured with these arguments,
# lacks what a configure leaves, or packages were just installed: the build itself configures
# again when a CMakeLists.txt or cmake/*.cmake changed.
rr_build() {
  RR_BUILD=${1:-$RR_ROOT/build}
  RR_DEVEL=${RR_DEVEL:-$RR_ROOT/devel}
  local type=${2:-Release} t0=$SECONDS
  local args=(-S "$RR_ROOT" -B "$RR_BUILD" -DCMAKE_BUILD_TYPE="$type"
    -DCATKIN_DEVEL_PREFIX="$RR_DEVEL" -DPYTHON_EXECUTABLE=/usr/bin/python3
    -DCATKIN_ENABLE_TESTING=ON)
  local stamp="$RR_BUILD/configure.args"
  mkdir -p "$RR_BUILD"
  if [ -n "${RR_INSTALLED:-}" ] || [ ! -f "$RR_BUILD/CMakeCache.txt" ] ||
    [ ! -f "$RR_BUILD/Makefile" ] || [ ! -f "$RR_DEVEL/setup.bash" ] ||
    [ "$(cat "$stamp" 2>/dev/null)" != "${args[*]}" ]; then
    rm -f "$stamp"
    rr_run_logged "$RR_BUILD/configure.log" "configuring ($type)" cmake "${args[@]}" || return 1
    printf '%s' "${args[*]}" >"$stamp"
  fi
  rr_run_logged "$RR_BUILD/build.log" "building nodes and tools" \
    cmake --build "$RR_BUILD" -j"$(nproc)" || return 1
  # catkin builds test executables only through its `tests` target.
  if [ "${RR_BUILD_TESTS:-1}" = 1 ]; then
    rr_run_logged "$RR_BUILD/build-tests.log" "building tests" \
      cmake --build "$RR_BUILD" -j"$(nproc)" --target tests || return 1
  fi
  rr_log "built in $((SECONDS - t0)) s (devel space ${RR_DEVEL#"$RR_ROOT"/}/)"
}

# Put the built package on ROS_PACKAGE_PATH (rosrun, rostest, rosservice find it).
rr_source() {
  # shellcheck disable=SC1091
  set +u
  source "$RR_DEVEL/setup.bash"
  set -u
}

# rr_alive PID: the process runs (it exists and has not ended: a child not yet waited for stays a
# zombie, which `kill -0` still finds).
rr_alive() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  stat=${stat##*) }
  [ "${stat%% *}" != Z ]
}

# rr_stop_child PID: stops a child that was sent a Ctrl-C (INT), waiting for it. A ROS node ends on
# INT once ros::init has set roscpp's handler; before that (rosrun still looking for it, the node
# loading) it ignores INT, as every command a script starts in the background does. Such a child
# gets TERM after 3 s and KILL after 3 s more, so that stopping never hangs on a node that was
# still starting (scripts/run did, for ever, when one node refused its world while another one
# started).
rr_stop_child() {
  local pid=$1 signal tries
  for signal in TERM KILL; do
    for ((tries = 0; tries < 30; tries++)); do
      rr_alive "$pid" || break 2
      sleep 0.1
    done
    kill "-$signal" "$pid" 2>/dev/null || true
  done
  wait "$pid" 2>/dev/null || true
}

# rr_stop PID...: a Ctrl-C (INT) to each, then rr_stop_child for each: the way a script stops the
# nodes and roscores it started in the background.
rr_stop() {
  local pid
  for pid in "$@"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "$@"; do rr_stop_child "$pid"; done
}

rr_master_online() { /usr/bin/python3 -c 'import rosgraph,sys; sys.exit(0 if rosgraph.is_master_online() else 1)' 2>/dev/null; }

# rr_wait_nodes TIMEOUT NODE...: wait until every named node has registered with the master
# (its publications, subscriptions and services are then known). Non-zero after TIMEOUT seconds.
rr_wait_nodes() {
  /usr/bin/python3 - "$@" <<'PY'
import signal  # Ctrl-C: no traceback (unless ignored, as in a background job)
signal.getsignal(signal.SIGINT) is signal.SIG_IGN or signal.signal(signal.SIGINT, signal.SIG_DFL)
import sys, time, rosgraph
timeout, wanted = float(sys.argv[1]), set(sys.argv[2:])
master, deadline = rosgraph.Master("/roomba_rrt_scripts"), time.time() + timeout
while time.time() < deadline:
    try:
        state = master.getSystemState()
        nodes = {n for group in state for _, ns in group for n in ns}
        if wanted <= nodes:
            sys.exit(0)
    except Exception:
        pass
    time.sleep(0.2)
sys.exit(1)
PY
}

# rr_registered_nodes NODE...: prints those of the named nodes that the master knows and that
# answer (space-separated; a registration left behind by a killed node does not count), nothing
# when none (or no master answers).
rr_registered_nodes() {
  /usr/bin/python3 - "$@" <<'PY'
import signal  # Ctrl-C: no traceback (unless ignored, as in a background job)
signal.getsignal(signal.SIGINT) is signal.SIG_IGN or signal.signal(signal.SIGINT, signal.SIG_DFL)
import socket, sys, xmlrpc.client, rosgraph
master = rosgraph.Master("/roomba_rrt_scripts")
try:
    state = master.getSystemState()
except Exception:
    sys.exit(0)
known = {n for group in state for _, ns in group for n in ns}
socket.setdefaulttimeout(2.0)
alive = []
for name in sys.argv[1:]:
    if name not in known:
        continue
    try:
        xmlrpc.client.ServerProxy(master.lookupNode(name)).getPid("/roomba_rrt_scripts")
        alive.append(name)
    except Exception:
        pass
print(" ".join(alive))
PY
}
