# Exploration (include/roomba_rrt/exploration/), ROS-free: frontiers of a map the robot builds and
# the nearest one it can drive to (roomba_exploration, over the geometry library's grid), and
# cleaning a home the robot has never seen (roomba_explore_clean: the mapper, the frontiers, the
# navigation and cleaning trees; roomba_coverage --unknown and roomba_bt ~unknown; and driving to a
# goal on the map it builds, roomba_nav_eval --unknown; with a map of the home that may be stale,
# --known-map: known_map, clean_known_map).

add_library(roomba_exploration src/exploration/frontiers.cpp)
target_include_directories(roomba_exploration PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_exploration PUBLIC roomba_geometry)

# The classic Roomba's cleaning (bumper and IR light bumper, no lidar): the map of what it swept
# and touched, the online boustrophedon, and the robot driving it.
add_library(roomba_bump_clean src/exploration/swept_map.cpp src/exploration/online_boustrophedon.cpp
  src/exploration/bump_clean.cpp)
target_link_libraries(roomba_bump_clean PUBLIC roomba_geometry roomba_mapping roomba_nav_core)

add_library(roomba_explore_clean src/exploration/built_map.cpp src/exploration/explore_clean.cpp
  src/exploration/navigate_unknown.cpp src/exploration/known_map.cpp
  src/exploration/clean_known_map.cpp)
target_link_libraries(roomba_explore_clean PUBLIC roomba_exploration roomba_mapping roomba_nav_core
  roomba_coverage_core roomba_world_planning roomba_bump_clean)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(exploration_test test/exploration/frontiers_test.cpp LINK roomba_exploration)
  roomba_rrt_gtest(online_boustrophedon_test test/exploration/online_boustrophedon_test.cpp
    LINK roomba_bump_clean)
  # Goals in a home the robot has never seen, through roomba_nav_eval's loop (--unknown).
  roomba_rrt_gtest(navigate_unknown_test test/exploration/navigate_unknown_test.cpp
    LINK roomba_nav_eval_run)
  # A stale map of the home (--known-map): cleaning and goals with its walls, its bad inputs.
  roomba_rrt_gtest(clean_known_map_test test/exploration/clean_known_map_test.cpp
    LINK roomba_coverage_run roomba_nav_eval_run)
endif()
