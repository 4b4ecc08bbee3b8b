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
  # tf2 (C++ and Python) and its tools (tf2_echo, view_frames), actionlib (C++ and Python)
  libtf2-dev libtf2-ros-dev python3-tf2-ros tf2-tools
  libactionlib-dev python3-actionlib python3-actionlib-tools
  # libraries of the ROS-free cores and the tools
  libyaml-cpp-dev libcairo2-dev libtinyxml2-dev
  # tests, benchmarks, fuzzing (clang's libFuzzer and sanitizer runtimes), pictures
  libgtest-dev librostest-dev python3-rostest python3-rosunit
  libompl-dev libbenchmark-dev
  clang libfuzzer-14-dev libclang-rt-14-dev
  rviz xvfb libgl1-mesa-dri imagemagick iproute2 procps
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
