# The world a robot lives in, read from a world file: the room's walls, furniture, the robots and
# the simulator's settings (config/roomba_world.yaml documents the format). ROS-free, below both
# the simulator and the planner, which read the same files.

add_library(roomba_world src/world/world.cpp)
target_include_directories(roomba_world PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_world PUBLIC roomba_geometry yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(world_test test/world/world_test.cpp)
  if(TARGET world_test)
    target_link_libraries(world_test roomba_world gtest_main)
    target_compile_definitions(world_test PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
  endif()
endif()
