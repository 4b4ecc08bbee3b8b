#!/usr/bin/env bash
# ctest entry of doc_commands_test.py: the built package on the ROS paths, a free master port.
set -euo pipefail
source "$(dirname "$0")/../integration/ros_test_env.bash"
trap cleanup_env EXIT
python3 "$here/doc_commands_test.py" "$root" "$RR_DEVEL"
