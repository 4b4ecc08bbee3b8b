# What every node shares: its private parameters read one way and the config folder it takes its
# default files from (node_params), and the watch that stops it when the master is gone for good
# (master_watch), maps to and from nav_msgs/OccupancyGrid (map_messages), how a node that
# serves long requests stops (shutdown_grace), and laser scans waiting for tf (scan_input).

add_library(roomba_node_common STATIC src/ros/node_params.cpp src/ros/master_watch.cpp
  src/ros/map_messages.cpp src/ros/shutdown_grace.cpp src/ros/scan_input.cpp)
target_include_directories(roomba_node_common PUBLIC ${catkin_INCLUDE_DIRS})
target_link_libraries(roomba_node_common PUBLIC roomba_geometry ${catkin_LIBRARIES})
# The source tree's config/, for a node run without the package on ROS_PACKAGE_PATH.
target_compile_definitions(roomba_node_common PRIVATE
  ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(map_messages_test test/nodes/map_messages_test.cpp LINK roomba_node_common ROS)
  roomba_rrt_gtest(message_parts_test test/nodes/message_parts_test.cpp LINK roomba_geometry ROS)
endif()
