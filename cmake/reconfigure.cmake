# dynamic_reconfigure: the .cfg files are generated in CMakeLists.txt (before catkin_package);
# here the tests that the .cfg ranges are the validated ones and that every node reconfigures.

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(reconfigure_ranges_test test/nodes/reconfigure_ranges_test.cpp
    LINK roomba_nav_core rrt_planning roomba_sim_core roomba_behavior_core ROS)
  add_rostest(test/nodes/reconfigure.test
    DEPENDENCIES roomba_sim roomba_fsm roomba_bt rrt_planner)
  # The install space on its own: installed executables, libraries, roomba_bt's two trees, and
  # reconfigure.test run by rostest from it.
  add_test(NAME install_space_test
    COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/test/integration/install_space_test.bash)
  set_tests_properties(install_space_test PROPERTIES
    ENVIRONMENT "RR_BUILD=${CMAKE_BINARY_DIR}" TIMEOUT 300)
endif()
