# The Roomba behaviours: ROS-free engines (FSM, BT) and the lab's behaviour on both, the
# roomba_fsm and roomba_bt nodes, the roomba_coverage tool, tests and the tick benchmark.

# tinyxml2 (libtinyxml2-dev) reads the behavior-tree files.
find_package(PkgConfig REQUIRED)
pkg_check_modules(TINYXML2 REQUIRED IMPORTED_TARGET tinyxml2)

add_library(roomba_behavior_core
  src/fsm/state_machine.cpp
  src/bt/status.cpp
  src/bt/control_node.cpp
  src/bt/sequence_node.cpp
  src/bt/sequence_with_memory.cpp
  src/bt/selector_node.cpp
  src/bt/reactive_sequence.cpp
  src/bt/reactive_selector.cpp
  src/bt/pipeline_sequence.cpp
  src/bt/rate_controller.cpp
  src/bt/recovery_node.cpp
  src/bt/inverter_node.cpp
  src/bt/repeat_node.cpp
  src/bt/retry_node.cpp
  src/bt/timeout_node.cpp
  src/bt/tree_factory.cpp
  src/behavior/roomba_params.cpp
  src/behavior/roomba_state.cpp
  src/behavior/motion_primitives.cpp
  src/behavior/roomba_behavior.cpp
  src/behavior/roomba_fsm.cpp
  src/behavior/roomba_tree.cpp
  src/behavior/roomba_bt.cpp
)
target_include_directories(roomba_behavior_core PUBLIC include)
target_link_libraries(roomba_behavior_core PUBLIC yaml-cpp PRIVATE PkgConfig::TINYXML2)
# The lab's tree exists once, in config/roomba_tree.xml: RoombaBt's default tree is that file's
# text, compiled in (reconfigured whenever the file changes).
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/config/roomba_tree.xml)
file(READ ${CMAKE_CURRENT_SOURCE_DIR}/config/roomba_tree.xml ROOMBA_LAB_TREE_XML)
configure_file(cmake/lab_tree_xml.h.in
  ${CMAKE_CURRENT_BINARY_DIR}/generated/roomba_rrt/behavior/lab_tree_xml.h @ONLY)
target_include_directories(roomba_behavior_core PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)

# The two nodes share their ROS adapter (parameters, subscriptions, timer, publications).
add_library(roomba_behavior_node STATIC src/nodes/behavior_node.cpp src/nodes/master_watch.cpp
  src/nodes/node_params.cpp)
target_include_directories(roomba_behavior_node PUBLIC ${catkin_INCLUDE_DIRS})
target_link_libraries(roomba_behavior_node PUBLIC roomba_behavior_core ${catkin_LIBRARIES})
add_dependencies(roomba_behavior_node ${${PROJECT_NAME}_EXPORTED_TARGETS}
  ${catkin_EXPORTED_TARGETS})

add_executable(roomba_fsm src/nodes/roomba_fsm_node.cpp)
target_link_libraries(roomba_fsm roomba_behavior_node)

# Headless coverage experiments: the simulation core and a behaviour in one process (its
# arguments, runs, statistics and pictures in src/tools/coverage_*).
add_executable(roomba_coverage src/tools/roomba_coverage.cpp src/tools/coverage_arguments.cpp
  src/tools/coverage_run.cpp src/tools/coverage_statistics.cpp src/tools/coverage_drawing.cpp)
target_link_libraries(roomba_coverage roomba_tools roomba_behavior_core)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(behavior_core_test
    test/behavior/state_machine_test.cpp
    test/behavior/control_nodes_test.cpp
    test/behavior/decorators_test.cpp
    test/behavior/tree_factory_test.cpp
    test/behavior/tree_file_format_test.cpp
    test/behavior/blackboard_ports_test.cpp
    test/behavior/nav_control_nodes_test.cpp
    test/behavior/roomba_params_test.cpp
    test/behavior/roomba_behavior_test.cpp
    test/behavior/roomba_bt_test.cpp
    test/behavior/fsm_bt_equivalence_test.cpp
  )
  if(TARGET behavior_core_test)
    target_link_libraries(behavior_core_test roomba_behavior_core PkgConfig::TINYXML2 gtest_main)
    target_compile_definitions(behavior_core_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  endif()

  # The roomba_coverage tool as a user runs it (its PNG's seed, its progress bar).
  catkin_add_gtest(roomba_coverage_test test/behavior/roomba_coverage_test.cpp)
  if(TARGET roomba_coverage_test)
    target_link_libraries(roomba_coverage_test gtest_main)
    target_compile_definitions(roomba_coverage_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
    add_dependencies(roomba_coverage_test roomba_coverage)
  endif()

  # Through real ROS: roomba_sim at 10x real time with either behaviour node.
  add_rostest_gtest(behavior_rostest test/behavior/roomba_fsm.test
    test/behavior/behavior_rostest.cpp)
  add_rostest(test/behavior/roomba_bt.test DEPENDENCIES behavior_rostest)
  add_rostest(test/behavior/roomba_behavior_startup.test DEPENDENCIES behavior_rostest)
  if(TARGET behavior_rostest)
    target_include_directories(behavior_rostest PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(behavior_rostest ${catkin_LIBRARIES})
    add_dependencies(behavior_rostest roomba_fsm roomba_bt roomba_sim
      ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()

  # rviz on a virtual X server (xvfb, imagemagick): the state text follows the moving robot.
  add_rostest_gtest(state_marker_rviz_test test/behavior/state_marker_rviz.test
    test/behavior/state_marker_rviz_test.cpp)
  if(TARGET state_marker_rviz_test)
    target_include_directories(state_marker_rviz_test PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(state_marker_rviz_test roomba_screen_capture ${catkin_LIBRARIES})
    add_dependencies(state_marker_rviz_test roomba_fsm roomba_sim
      ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()
endif()

# Nanoseconds per tick: the lab tree, the FSM and a hand-written switch (bench/roomba_switch.h).
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(behavior_bench EXCLUDE_FROM_ALL bench/behavior_bench.cpp)
  target_link_libraries(behavior_bench roomba_nav_core benchmark::benchmark)
  target_compile_definitions(behavior_bench PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
endif()

# Navigation (issue 10): the path follower, the planner interface, the navigation leaves and
# trees. ROS-free; a library of its own so the lab's behaviours do not depend on the planner.
find_package(Threads REQUIRED)
add_library(roomba_nav_core
  src/behavior/path_follower.cpp
  src/behavior/motion_guard.cpp
  src/behavior/path_planner.cpp
  src/behavior/nav_leaves.cpp
  src/behavior/nav_bt.cpp
  src/behavior/nav_eval.cpp
)
target_include_directories(roomba_nav_core PUBLIC include)
target_link_libraries(roomba_nav_core PUBLIC roomba_behavior_core rrt_planning roomba_sim_core
  Threads::Threads)

# roomba_bt: the lab's tree, or a navigation tree behind move_base's interface (the move_base
# action, /move_base_simple/goal, tf2, ~plan; the ~plan_path client). The conversions are
# unit-tested without a master (nav_ros_test).
add_executable(roomba_bt src/nodes/roomba_bt_node.cpp src/nodes/nav_behavior.cpp
  src/nodes/nav_ros.cpp src/nodes/planner_ros.cpp)
target_link_libraries(roomba_bt roomba_behavior_node roomba_nav_core)
add_dependencies(roomba_bt ${${PROJECT_NAME}_EXPORTED_TARGETS})

# Goal message to first non-zero /cmd_vel over ROS, in wall time (scripts/bench).
add_executable(nav_latency_probe bench/nav_latency_probe.cpp)
target_include_directories(nav_latency_probe PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(nav_latency_probe ${catkin_LIBRARIES})

# Navigation without ROS: random goals in one process (simulator, tree, planner).
add_executable(roomba_nav_eval src/tools/roomba_nav_eval.cpp)
target_link_libraries(roomba_nav_eval roomba_nav_core roomba_tools)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(nav_core_test
    test/behavior/path_follower_test.cpp
    test/behavior/nav_bt_test.cpp
    test/behavior/nav_leaves_test.cpp
    test/behavior/nav_eval_test.cpp
  )
  if(TARGET nav_core_test)
    target_link_libraries(nav_core_test roomba_nav_core gtest_main)
    target_compile_definitions(nav_core_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  endif()
  # 12 000 goals in three rooms (about 30 s): its own test, so the quick ones stay quick.
  catkin_add_gtest(bump_free_navigation_test test/behavior/bump_free_navigation_test.cpp
    TIMEOUT 600)
  if(TARGET bump_free_navigation_test)
    target_link_libraries(bump_free_navigation_test roomba_nav_core gtest_main)
    target_compile_definitions(bump_free_navigation_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config"
      ROOMBA_RRT_TEST_DIR="${CMAKE_CURRENT_SOURCE_DIR}/test")
  endif()
  # roomba_bt's navigation conversions, without a master.
  catkin_add_gtest(nav_ros_test test/behavior/nav_ros_test.cpp src/nodes/nav_ros.cpp)
  if(TARGET nav_ros_test)
    target_include_directories(nav_ros_test PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(nav_ros_test roomba_nav_core ${catkin_LIBRARIES} gtest_main)
    add_dependencies(nav_ros_test ${${PROJECT_NAME}_EXPORTED_TARGETS})
    target_compile_definitions(nav_ros_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  endif()

  # roomba_bt's navigation through real ROS: the simulator in the furnished room, rrt_planner.
  add_rostest_gtest(nav_rostest test/behavior/nav_goal.test test/behavior/nav_rostest.cpp)
  add_rostest(test/behavior/nav_action.test DEPENDENCIES nav_rostest)
  # Issue 13: two named robots, each with its own navigation roomba_bt, one shared rrt_planner.
  add_rostest(test/behavior/nav_two_robots.test DEPENDENCIES nav_rostest)
  if(TARGET nav_rostest)
    target_include_directories(nav_rostest PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(nav_rostest ${catkin_LIBRARIES})
    add_dependencies(nav_rostest roomba_bt roomba_sim rrt_planner
      ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()

  # Its own executable: it replaces operator new to count allocations.
  catkin_add_gtest(nav_allocation_test test/behavior/nav_allocation_test.cpp)
  if(TARGET nav_allocation_test)
    target_link_libraries(nav_allocation_test roomba_nav_core gtest_main)
    target_compile_definitions(nav_allocation_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  endif()
endif()
