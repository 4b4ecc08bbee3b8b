# Navigation: the path follower and its motion guard, the planner interface, the navigation leaves
# and trees (src/navigation/), ROS-free, a library of its own so that the lab's behaviours do not
# depend on the planner; the roomba_bt node, which runs the lab's tree or a navigation tree; the
# roomba_nav_eval tool; tests and the latency probe.
find_package(Threads REQUIRED)
add_library(roomba_nav_core
  src/navigation/path_follower.cpp
  src/navigation/guarded_follower.cpp
  src/navigation/motion_guard.cpp
  src/navigation/pose_predictor.cpp
  src/navigation/command_latency.cpp
  src/navigation/path_checker.cpp
  src/navigation/path_planner.cpp
  src/navigation/nav_leaves.cpp
  src/navigation/nav_bt.cpp
)
target_include_directories(roomba_nav_core PUBLIC include)
target_link_libraries(roomba_nav_core PUBLIC roomba_behavior_core roomba_world_planning
  roomba_robot Threads::Threads)

# roomba_bt: the lab's tree, or a navigation tree behind move_base's interface (the move_base
# action, /move_base_simple/goal, tf2, ~plan; the ~plan_path client), or with ~unknown exploring
# and cleaning from `scan`. The conversions are unit-tested without a master (nav_ros_test).
add_executable(roomba_bt src/nodes/roomba_bt_node.cpp src/ros/nav_behavior.cpp
  src/ros/nav_ros.cpp src/ros/planner_ros.cpp)
target_link_libraries(roomba_bt roomba_behavior_node roomba_nav_core roomba_coverage_core
  roomba_explore_clean roomba_node_common)
add_dependencies(roomba_bt ${${PROJECT_NAME}_EXPORTED_TARGETS})

# Goal message to first non-zero /cmd_vel over ROS, in wall time (scripts/bench).
add_executable(nav_latency_probe bench/nav_latency_probe.cpp)
target_include_directories(nav_latency_probe PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(nav_latency_probe ${catkin_LIBRARIES})

# Navigation without ROS: random goals in one process (simulator, tree, planner). Its run loop
# (src/tools/nav_eval_run.*) is a library of its own, for the tests that drive navigation with it.
add_library(roomba_nav_eval_run STATIC src/tools/nav_eval_run.cpp)
target_include_directories(roomba_nav_eval_run PUBLIC ${PROJECT_SOURCE_DIR}/src/tools)
target_link_libraries(roomba_nav_eval_run PUBLIC roomba_nav_core roomba_sim_core roomba_explore_clean
  roomba_sensors)
add_executable(roomba_nav_eval src/tools/roomba_nav_eval.cpp)
target_link_libraries(roomba_nav_eval roomba_nav_eval_run roomba_tools)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(nav_core_test test/navigation/path_follower_test.cpp
    test/navigation/nav_bt_test.cpp test/navigation/nav_leaves_test.cpp
    test/navigation/pose_predictor_test.cpp test/navigation/guarded_follower_test.cpp
    test/navigation/command_latency_test.cpp
    LINK roomba_nav_core roomba_sim_core)
  # roomba_nav_eval's run loop: goals drawn, outcomes counted, reproducible.
  roomba_rrt_gtest(nav_eval_run_test test/tools/nav_eval_run_test.cpp LINK roomba_nav_eval_run)
  # 12 000 goals in three rooms (about 30 s): its own test, so the quick ones stay quick.
  roomba_rrt_gtest(bump_free_navigation_test test/navigation/bump_free_navigation_test.cpp
    LINK roomba_nav_eval_run)
  # roomba_bt's navigation conversions, without a master.
  roomba_rrt_gtest(nav_ros_test test/navigation/nav_ros_test.cpp src/ros/nav_ros.cpp
    LINK roomba_nav_core ROS)

  # roomba_bt's navigation through real ROS: the simulator in the furnished room, rrt_planner.
  add_rostest_gtest(nav_rostest test/navigation/nav_goal.test test/navigation/nav_rostest.cpp)
  add_rostest(test/navigation/nav_action.test DEPENDENCIES nav_rostest)
  # Two named robots, each with its own navigation roomba_bt, one shared rrt_planner.
  add_rostest(test/navigation/nav_two_robots.test DEPENDENCIES nav_rostest)
  # A map world: make_plan between rooms and a goal through a doorway, in the package's apartment
  # and (make_plan only) in willow_full, a real building's floor, when ../shared/maps is there.
  add_rostest(test/navigation/nav_map.test DEPENDENCIES nav_rostest)
  # Systematic cleaning: the coverage tree cleans the furnished room, then stands still.
  add_rostest(test/navigation/clean.test DEPENDENCIES nav_rostest)
  # A home it has never seen: roomba_mapper's /map, roomba_bt ~unknown explores, then cleans.
  add_rostest(test/navigation/clean_unknown.test DEPENDENCIES nav_rostest)
  # The classic Roomba there: no lidar, roomba_bt ~unknown cleans by touch.
  add_rostest(test/navigation/clean_by_touch.test DEPENDENCIES nav_rostest)
  # And navigation there: roomba_bt ~unknown with the navigation tree takes goals on that map.
  add_rostest(test/navigation/nav_unknown.test DEPENDENCIES nav_rostest)
  # With a stale map of the home (~known_map: its walls, not its furniture): goals, cleaning.
  add_rostest(test/navigation/nav_known_map.test DEPENDENCIES nav_rostest)
  add_rostest(test/navigation/clean_known_map.test DEPENDENCIES nav_rostest)
  if(EXISTS ${PROJECT_SOURCE_DIR}/../shared/maps/willow_full.yaml)
    add_rostest(test/navigation/nav_map_willow.test DEPENDENCIES nav_rostest)
  elseif("$ENV{CI}" STREQUAL "true")
    message(FATAL_ERROR "nav_map_willow.test needs ${PROJECT_SOURCE_DIR}/../shared/maps/willow_full.yaml"
      " (ros-simulation/stage_ros, world/willow-full.pgm; doc/testing.md#the-shared-maps)")
  else()
    message(STATUS "nav_map_willow.test is not run: it needs ../shared/maps/willow_full.yaml"
      " (ros-simulation/stage_ros, world/willow-full.pgm; doc/testing.md#the-shared-maps)")
  endif()
  if(TARGET nav_rostest)
    target_include_directories(nav_rostest PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(nav_rostest roomba_geometry ${catkin_LIBRARIES})
    add_dependencies(nav_rostest roomba_bt roomba_sim rrt_planner roomba_mapper
      ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()

  # Its own executable: it replaces operator new to count allocations.
  roomba_rrt_gtest(nav_allocation_test test/navigation/nav_allocation_test.cpp
    LINK roomba_nav_core roomba_sim_core)
endif()
