# Keyboard teleop: the ROS-free key-to-command library, the roomba_teleop node and its tests.

add_library(roomba_teleop_core src/teleop/keyboard_teleop.cpp)
target_include_directories(roomba_teleop_core PUBLIC include)

add_executable(roomba_teleop src/nodes/roomba_teleop_node.cpp)
target_link_libraries(roomba_teleop roomba_teleop_core roomba_node_common)
add_dependencies(roomba_teleop ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(teleop_core_test test/teleop/keyboard_teleop_test.cpp LINK roomba_teleop_core)
  # roomba_teleop on a pseudo-terminal driving roomba_sim through a real master.
  add_test(NAME teleop_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/teleop_test.bash)
  set_tests_properties(teleop_test PROPERTIES
    ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}" TIMEOUT 120)
endif()
