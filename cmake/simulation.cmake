# The simulated Roomba: ROS-free core library, the roomba_sim node, tests and benchmarks.

add_library(roomba_sim_core
  src/sim/contact.cpp
  src/sim/coverage_grid.cpp
  src/sim/simulator.cpp
  src/sim/robot_grid.cpp
  src/sim/multi_robot_simulator.cpp
)
target_include_directories(roomba_sim_core PUBLIC include)
target_link_libraries(roomba_sim_core PUBLIC roomba_robot roomba_world)
# sqrt without the errno branch: the coverage grid takes one per row of every step.
target_compile_options(roomba_sim_core PRIVATE -fno-math-errno)

# The node wires parameters, topics and timers; src/ros/sim_ros.cpp builds its messages.
add_executable(roomba_sim src/nodes/roomba_sim_node.cpp src/ros/roomba_sim.cpp src/ros/sim_ros.cpp)
target_link_libraries(roomba_sim roomba_sim_core roomba_sensors roomba_node_common)
add_dependencies(roomba_sim ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

# Measures the node's sustained real-time factor while reading every /odom (doc/performance.md).
add_executable(sim_rtf_probe bench/sim_rtf_probe.cpp)
target_include_directories(sim_rtf_probe PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(sim_rtf_probe ${catkin_LIBRARIES})

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(sim_core_test test/sim/contact_test.cpp
    test/sim/coverage_grid_test.cpp test/sim/simulator_test.cpp
    test/sim/multi_robot_simulator_test.cpp test/sim/robot_grid_test.cpp test/sim/map_world_test.cpp
    LINK roomba_sim_core)

  # roomba_sim's messages (odometry, tf, bumper, markers, coverage map), without a master.
  roomba_rrt_gtest(sim_ros_test test/sim/sim_ros_test.cpp src/ros/sim_ros.cpp
    LINK roomba_sim_core roomba_sensors ROS)

  # A rostest whose test node (gtest) talks to roomba_sim through a real master.
  function(roomba_sim_rostest target launch_file source)
    add_rostest_gtest(${target} ${launch_file} ${source})
    if(TARGET ${target})
      target_include_directories(${target} PRIVATE ${catkin_INCLUDE_DIRS})
      target_link_libraries(${target} ${catkin_LIBRARIES})
      add_dependencies(${target} roomba_sim ${${PROJECT_NAME}_EXPORTED_TARGETS})
    endif()
  endfunction()

  # Driving, bumper, clock, bad commands, reset; in simulated time (10x) and in wall-clock time.
  roomba_sim_rostest(sim_driving_test test/sim/sim_driving.test test/sim/sim_driving_test.cpp)
  add_rostest(test/sim/sim_wall_clock.test DEPENDENCIES sim_driving_test)
  # An invalid world stops the node, naming the parameter.
  roomba_sim_rostest(sim_invalid_world_test test/sim/sim_invalid_world.test
    test/sim/sim_invalid_world_test.cpp)
  # What a user sees in rviz: Xvfb, programs on it, screen grabs (imagemagick); also behavior.cmake.
  add_library(roomba_screen_capture STATIC EXCLUDE_FROM_ALL test/common/screen_capture.cpp)
  # Master restarted, then roomba_sim restarted, under scripts/run's supervision: the
  # robot drives again within 5 s (a bash script; it starts its own roscore on a free port).
  add_test(NAME master_restart_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/master_restart_test.bash)
  set_tests_properties(master_restart_test PROPERTIES
    ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}" TIMEOUT 180)
  # scripts/run: --help, a node refusing its world stops everything (exit 1), _param:= reaches
  # the node, a second run against the same master is refused.
  add_test(NAME scripts_run_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/scripts_run_test.bash)
  set_tests_properties(scripts_run_test PROPERTIES
    ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}" TIMEOUT 420)
  # scripts/run's rviz view on a map: whole when small, zoomed in on the robot when large.
  add_test(NAME rviz_map_view_test
    COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/rviz_map_view_test.py)
  # Node parameters out of range stop the node naming them; Ctrl-C stops within 1 s.
  add_test(NAME node_parameters_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/node_parameters_test.bash)
  set_tests_properties(node_parameters_test PROPERTIES
    ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}" TIMEOUT 300)
  # Two machines (network namespaces joined by a veth pair) against one master:
  # roscore + roomba_sim on one, roomba_fsm + rrt_planner on the other. Needs root and ip netns;
  # without them it exits 77 and ctest shows it as skipped.
  add_test(NAME two_machines_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/two_machines_test.bash)
  set_tests_properties(two_machines_test PROPERTIES
    ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}" TIMEOUT 300 SKIP_RETURN_CODE 77)
  # rviz on a virtual X server (xvfb, imagemagick): the config shows robot, walls, coverage map.
  roomba_sim_rostest(sim_rviz_screenshot_test test/sim/sim_rviz.test
    test/sim/sim_rviz_screenshot_test.cpp)
  if(TARGET sim_rviz_screenshot_test)
    target_link_libraries(sim_rviz_screenshot_test roomba_screen_capture)
  endif()
  # A map world: /map as map_server publishes the file, the robot never ends on a wall.
  roomba_sim_rostest(sim_map_test test/sim/sim_map.test test/sim/sim_map_test.cpp)
  if(TARGET sim_map_test)
    target_link_libraries(sim_map_test roomba_geometry)
    target_compile_definitions(sim_map_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
    add_dependencies(sim_map_test roomba_fsm roomba_mapper)
  endif()
  # ~publish_map false: the true map stays the simulator's; /map is roomba_mapper's.
  add_rostest(test/sim/sim_map_hidden.test DEPENDENCIES sim_map_test)
  # Range sensors: the LDS's LaserScan and tf, one robot at 10x and two named robots at 3x.
  roomba_sim_rostest(sim_scan_test test/sim/sim_scan.test test/sim/sim_scan_test.cpp)
  add_rostest(test/sim/sim_scan_two_robots.test DEPENDENCIES sim_scan_test)
  # Two named robots, each driven by its own roomba_fsm under its namespace.
  roomba_sim_rostest(sim_two_robots_test test/sim/sim_two_robots.test
    test/sim/sim_two_robots_test.cpp)
  if(TARGET sim_two_robots_test)
    add_dependencies(sim_two_robots_test roomba_fsm)
  endif()
endif()

# Google Benchmark (libbenchmark-dev): core steps per second. Built only when it is installed.
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(sim_bench bench/sim_bench.cpp)
  target_link_libraries(sim_bench roomba_sim_core benchmark::benchmark)
  target_compile_definitions(sim_bench PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
endif()
