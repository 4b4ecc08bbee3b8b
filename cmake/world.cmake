# The world a robot lives in, read from a world file: the room's walls, furniture, the robots and
# the simulator's settings (config/roomba_world.yaml documents the format). ROS-free, below both
# the simulator and the planner, which read the same files.

add_library(roomba_world src/world/world.cpp src/world/world_file.cpp)
target_include_directories(roomba_world PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_world PUBLIC roomba_geometry roomba_sensor_spec yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(world_test test/world/world_test.cpp LINK roomba_world)
endif()
