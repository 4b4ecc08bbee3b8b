# The plane geometry shared by the simulator (contact, bumper) and the planner (collision checks):
# a small ROS-free library and its brute-force tests.

add_library(roomba_geometry src/geometry/geometry.cpp)
target_include_directories(roomba_geometry PUBLIC ${PROJECT_SOURCE_DIR}/include)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(geometry_test test/geometry/geometry_test.cpp)
  if(TARGET geometry_test)
    target_link_libraries(geometry_test roomba_geometry gtest_main)
  endif()
endif()
