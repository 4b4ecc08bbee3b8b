# A map the robot builds (doc/simulation.md, "Mapping"): the log-odds occupancy grid updated from
# scans and the bumper, saving it as map_server's map_saver does, and its comparison with the true
# world (roomba_mapping, ROS-free); the roomba_mapper node and the roomba_map_saver tool.

add_library(roomba_mapping src/mapping/occupancy_mapper.cpp src/mapping/map_saver.cpp
  src/mapping/map_accuracy.cpp)
target_include_directories(roomba_mapping PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_mapping PUBLIC roomba_geometry roomba_world roomba_sensor_spec)
target_compile_options(roomba_mapping PRIVATE -fno-math-errno)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(mapping_test test/mapping/occupancy_mapper_test.cpp
    test/mapping/map_saver_test.cpp LINK roomba_mapping roomba_sensors)
endif()
