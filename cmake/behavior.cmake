# The Roomba behaviours: ROS-free engines (FSM, BT) and the lab's behaviour on both, the
# roomba_fsm node (roomba_bt, which also navigates, is in navigation.cmake), the roomba_coverage
# tool, tests and the tick benchmark.

# tinyxml2 (libtinyxml2-dev) reads the behavior-tree files.
find_package(PkgConfig REQUIRED)
pkg_check_modules(TINYXML2 REQUIRED IMPORTED_TARGET tinyxml2)

add_library(roomba_behavior_core
  src/fsm/state_machine.cpp
  src/bt/status.cpp
  src/bt/tree_node.cpp
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
  src/bt/keep_running_until_failure.cpp
  src/bt/delay_node.cpp
  src/bt/sleep_node.cpp
  src/bt/parallel_node.cpp
  src/bt/parallel_all_node.cpp
  src/bt/if_then_else_node.cpp
  src/bt/while_do_else_node.cpp
  src/bt/switch_node.cpp
  src/bt/run_once_node.cpp
  src/bt/entry_updated.cpp
  src/bt/try_catch_node.cpp
  src/bt/script.cpp
  src/bt/node_conditions.cpp
  src/bt/script_node.cpp
  src/bt/precondition_node.cpp
  src/bt/blackboard_nodes.cpp
  src/bt/bt_log.cpp
  src/bt/bt_file_logger.cpp
  src/bt/tree_factory.cpp
  src/bt/tree_monitor.cpp
  src/bt/groot2_protocol.cpp
  src/bt/xml_parsing.cpp
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

# Groot2 live monitoring on ZeroMQ (libzmq3-dev, cppzmq-dev): the server thread of roomba_bt.
pkg_check_modules(ZMQ REQUIRED IMPORTED_TARGET libzmq)
add_library(roomba_bt_groot2 STATIC src/bt/groot2_server.cpp)
target_link_libraries(roomba_bt_groot2 PUBLIC roomba_behavior_core PRIVATE PkgConfig::ZMQ)
set_target_properties(roomba_bt_groot2 PROPERTIES POSITION_INDEPENDENT_CODE ON)

# The two nodes share their ROS adapter (parameters, subscriptions, timer, publications).
add_library(roomba_behavior_node STATIC src/ros/behavior_node.cpp src/ros/tree_watch.cpp)
target_link_libraries(roomba_behavior_node PUBLIC roomba_behavior_core roomba_bt_groot2
  roomba_node_common)
add_dependencies(roomba_behavior_node ${${PROJECT_NAME}_EXPORTED_TARGETS}
  ${catkin_EXPORTED_TARGETS})

add_executable(roomba_fsm src/nodes/roomba_fsm_node.cpp)
target_link_libraries(roomba_fsm roomba_behavior_node)

# Headless coverage experiments: the simulation core and a behaviour in one process (its
# arguments and runs, the cleaning of an unknown world: roomba_coverage_run, also used by
# mapping_bench; its statistics and pictures in src/tools/coverage_*).
add_library(roomba_coverage_run STATIC src/tools/coverage_arguments.cpp src/tools/coverage_run.cpp)
target_link_libraries(roomba_coverage_run PUBLIC roomba_tools roomba_behavior_core
  roomba_coverage_core roomba_explore_clean roomba_sensors)
add_executable(roomba_coverage src/tools/roomba_coverage.cpp src/tools/coverage_statistics.cpp
  src/tools/coverage_drawing.cpp)
target_link_libraries(roomba_coverage roomba_coverage_run)

if(CATKIN_ENABLE_TESTING)
  # roomba_coverage --unknown in process: exploring and cleaning a world the robot does not know.
  roomba_rrt_gtest(explore_clean_test test/tools/explore_clean_test.cpp LINK roomba_coverage_run)
  # The classic Roomba (bumper and IR light bumper, no lidar) cleaning a world it does not know.
  roomba_rrt_gtest(bump_clean_test test/tools/bump_clean_test.cpp LINK roomba_coverage_run)
endif()

if(CATKIN_ENABLE_TESTING)
  # The engines: the finite state machine, and the behavior tree's nodes, factory and files.
  roomba_rrt_gtest(fsm_test test/fsm/state_machine_test.cpp LINK roomba_behavior_core)
  roomba_rrt_gtest(bt_test test/bt/control_nodes_test.cpp test/bt/decorators_test.cpp
    test/bt/tree_factory_test.cpp test/bt/tree_file_format_test.cpp
    test/bt/blackboard_ports_test.cpp test/bt/nav_control_nodes_test.cpp
    test/bt/standard_nodes_test.cpp test/bt/script_test.cpp
    test/bt/bt_log_test.cpp test/bt/skipped_test.cpp
    LINK roomba_behavior_core PkgConfig::TINYXML2)
  # Watching a tree: the monitor's statuses, Groot2's protocol, and its server over ZeroMQ.
  roomba_rrt_gtest(bt_monitor_test test/bt/tree_monitor_test.cpp test/bt/groot2_protocol_test.cpp
    test/bt/groot2_server_test.cpp LINK roomba_bt_groot2 PkgConfig::ZMQ PkgConfig::TINYXML2)

  # The lab's behaviour: its constants, the FSM and the tree, and their equivalence.
  roomba_rrt_gtest(behavior_core_test test/behavior/roomba_params_test.cpp
    test/behavior/roomba_behavior_test.cpp test/behavior/roomba_bt_test.cpp
    test/behavior/fsm_bt_equivalence_test.cpp LINK roomba_behavior_core)

  # The roomba_coverage tool as a user runs it (its PNG's seed, its progress bar).
  roomba_rrt_gtest(roomba_coverage_test test/tools/roomba_coverage_test.cpp DEPENDS roomba_coverage)

  # Through real ROS: roomba_sim at 10x real time with either behaviour node.
  add_rostest_gtest(behavior_rostest test/behavior/roomba_fsm.test
    test/behavior/behavior_rostest.cpp)
  add_rostest(test/behavior/roomba_bt.test DEPENDENCIES behavior_rostest)
  add_rostest(test/behavior/roomba_behavior_startup.test DEPENDENCIES behavior_rostest)
  # roomba_bt's Groot2 server through a Python client of the protocol (python3-zmq).
  add_rostest(test/behavior/groot2_monitor.test DEPENDENCIES roomba_bt roomba_sim)
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
