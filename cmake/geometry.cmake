# The plane geometry shared by the simulator (contact, bumper) and the planner (collision checks):
# a small ROS-free library and its brute-force tests.

add_library(roomba_geometry src/geometry/geometry.cpp)
target_include_directories(roomba_geometry PUBLIC ${PROJECT_SOURCE_DIR}/include)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(geometry_test test/geometry/geometry_test.cpp LINK roomba_geometry)
endif()
