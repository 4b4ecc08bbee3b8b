# Exploration (include/roomba_rrt/exploration/): frontiers of a map the robot builds, and the nearest one it can
# drive to. ROS-free; over the geometry library's grid and clearance map.

add_library(roomba_exploration src/exploration/frontiers.cpp)
target_include_directories(roomba_exploration PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_exploration PUBLIC roomba_geometry)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(exploration_test test/exploration/frontiers_test.cpp LINK roomba_exploration)
endif()
