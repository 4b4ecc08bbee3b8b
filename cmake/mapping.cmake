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

# The node: scans, bumper and tf in, the map out (gmapping's interface).
add_executable(roomba_mapper src/nodes/roomba_mapper_node.cpp src/ros/roomba_mapper.cpp)
target_link_libraries(roomba_mapper roomba_mapping roomba_node_common)
add_dependencies(roomba_mapper ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})
# map_server's map_saver (Debian ships no map_server).
add_executable(roomba_map_saver src/nodes/roomba_map_saver_node.cpp)
target_link_libraries(roomba_map_saver roomba_mapping roomba_node_common)

if(CATKIN_ENABLE_TESTING)
  # The node's conversions (scan, tf pose, parameters' names), without a master.
  roomba_rrt_gtest(mapper_ros_test test/mapping/mapper_ros_test.cpp src/ros/roomba_mapper.cpp
    LINK roomba_mapping roomba_node_common ROS)
  # roomba_sim + roomba_mapper: /map gets published with the walls where the world has them,
  # ~dynamic_map answers the same, and roomba_map_saver writes it so that the world reads back.
  add_rostest_gtest(mapper_rostest test/mapping/mapper.test test/mapping/mapper_rostest.cpp)
  if(TARGET mapper_rostest)
    target_include_directories(mapper_rostest PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(mapper_rostest roomba_mapping roomba_node_common ${catkin_LIBRARIES})
    target_compile_definitions(mapper_rostest PRIVATE
      ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")
    add_dependencies(mapper_rostest roomba_sim roomba_mapper roomba_map_saver
      ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()
endif()

# The accuracy and update benchmark (scripts/bench): the simulator, its LDS and the cleaning tree
# in process (as roomba_coverage), feeding the mapper. With MRPT's occupancy grid
# (libmrpt-maps-dev, optional: not a dependency of the package) it also times MRPT's update.
find_package(mrpt-maps QUIET)
add_executable(mapping_bench EXCLUDE_FROM_ALL bench/mapping_bench.cpp)
target_include_directories(mapping_bench PRIVATE ${PROJECT_SOURCE_DIR}/bench)
target_link_libraries(mapping_bench roomba_coverage_run)
target_compile_definitions(mapping_bench PRIVATE
  ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
if(mrpt-maps_FOUND)
  target_link_libraries(mapping_bench mrpt::maps)
  target_compile_definitions(mapping_bench PRIVATE ROOMBA_RRT_WITH_MRPT)
  message(STATUS "roomba_rrt benchmarks: MRPT ${mrpt-maps_VERSION} found; mapping_bench compares")
endif()
