# Shared set-up for scripts/run, scripts/test, scripts/bench and scripts/figures.
# Source it; it defines functions only. Works on a fresh Debian 12 machine (as root, or with sudo).

# Debian's ROS needs Debian's Python (the one that has catkin_pkg), whatever else is on PATH.
export PATH=/usr/bin:/bin:$PATH

RR_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

# Every Debian package the project builds, runs, tests and benchmarks with.
RR_PACKAGES=(
  build-essential cmake pkg-config
  catkin libroscpp-dev ros-message-generation ros-message-runtime
  libstd-msgs-dev libstd-srvs-dev libgeometry-msgs-dev libnav-msgs-dev
  libvisualization-msgs-dev libros-rosgraph-msgs-dev libroslib-dev libtf2-ros-dev libtf2-dev
  python3-std-msgs python3-std-srvs python3-geometry-msgs python3-nav-msgs
  python3-visualization-msgs python3-genpy
  librostest-dev python3-rostest python3-roslaunch python3-rosnode python3-rosservice
  python3-rostopic python3-rosgraph rosbash ros-core
  libgtest-dev libyaml-cpp-dev libcairo2-dev libtinyxml2-dev
  libompl-dev libbenchmark-dev
  rviz xvfb libgl1-mesa-dri imagemagick
)

rr_log() { printf '\033[1m[roomba_rrt]\033[0m %s\n' "$*" >&2; }

# Install whatever Debian packages are missing (nothing to do, and no network, when all are there).
rr_install_deps() {
  local missing=() p
  for p in "${RR_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  rr_log "installing missing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
    "${missing[@]}" >/dev/null
}

# rr_build [BUILD_DIR] [BUILD_TYPE]: configure and build the package; sets RR_BUILD and RR_DEVEL.
# The catkin devel space (nodes, tools, setup.bash) goes to devel/ beside build/, not inside it:
# rosrun ignores every executable below <package>/build/, and the package is the repository root.
rr_build() {
  RR_BUILD=${1:-$RR_ROOT/build}
  RR_DEVEL=${RR_DEVEL:-$RR_ROOT/devel}
  local type=${2:-Release}
  rr_log "building in $RR_BUILD ($type), devel space $RR_DEVEL"
  mkdir -p "$RR_BUILD"
  cmake -S "$RR_ROOT" -B "$RR_BUILD" -DCMAKE_BUILD_TYPE="$type" -DCATKIN_DEVEL_PREFIX="$RR_DEVEL" \
    -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=ON >"$RR_BUILD/configure.log" 2>&1 ||
    { cat "$RR_BUILD/configure.log"; return 1; }
  # catkin builds test executables only through its `tests` target.
  cmake --build "$RR_BUILD" -j"$(nproc)"
  if [ "${RR_BUILD_TESTS:-1}" = 1 ]; then cmake --build "$RR_BUILD" -j"$(nproc)" --target tests; fi
}

# Put the built package on ROS_PACKAGE_PATH (rosrun, rostest, rosservice find it).
rr_source() {
  # shellcheck disable=SC1091
  set +u
  source "$RR_DEVEL/setup.bash"
  set -u
}

rr_master_online() { /usr/bin/python3 -c 'import rosgraph,sys; sys.exit(0 if rosgraph.is_master_online() else 1)' 2>/dev/null; }
