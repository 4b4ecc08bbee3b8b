# Coverage planning: the ROS-free library that plans rows and transits sweeping all the floor a
# robot can reach (boustrophedon decomposition of the disc's free space), its tests and benchmark.

add_library(roomba_coverage_planning src/coverage/free_space.cpp
  src/coverage/reachable_floor.cpp src/coverage/boustrophedon.cpp src/coverage/cell_order.cpp
  src/coverage/wall_loop.cpp src/coverage/coverage_planner.cpp src/coverage/touch_up.cpp
  src/coverage/tour.cpp src/coverage/joined_legs.cpp)
target_include_directories(roomba_coverage_planning PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_coverage_planning PUBLIC roomba_world)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(coverage_planner_test test/coverage/coverage_planner_test.cpp
    LINK roomba_coverage_planning)
  roomba_rrt_gtest(wall_loop_test test/coverage/wall_loop_test.cpp LINK roomba_coverage_planning)
  roomba_rrt_gtest(boustrophedon_test test/coverage/boustrophedon_test.cpp
    LINK roomba_coverage_planning)
  roomba_rrt_gtest(tour_test test/coverage/tour_test.cpp LINK roomba_coverage_planning)
  roomba_rrt_gtest(joined_legs_test test/coverage/joined_legs_test.cpp
    LINK roomba_coverage_planning)
endif()

# coverage_bench: time to plan the furnished room's coverage (target ≤ 10 ms), and a whole map.
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(coverage_bench bench/coverage_bench.cpp)
  target_link_libraries(coverage_bench roomba_coverage_planning benchmark::benchmark)
  target_compile_definitions(coverage_bench PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config"
    ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
endif()

# The cleaning tree's leaves (config/roomba_coverage_tree.xml), run by navigation::NavBt beside the
# navigation leaves: they plan with the coverage planner and drive with the navigation's follower.
add_library(roomba_coverage_core src/coverage/coverage_leaves.cpp)
target_include_directories(roomba_coverage_core PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_coverage_core PUBLIC roomba_coverage_planning roomba_nav_core)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(coverage_leaves_test test/coverage/coverage_leaves_test.cpp
    LINK roomba_coverage_core roomba_sim_core)
endif()

# coverage_planner: the coverage planner as a ROS service (~plan_coverage, roomba_rrt/PlanCoverage)
# in ~world_file's world or on /map; coverage_ros turns requests and plans into messages.
add_executable(coverage_planner src/nodes/coverage_planner_node.cpp src/ros/coverage_ros.cpp)
target_link_libraries(coverage_planner roomba_coverage_planning roomba_node_common)
add_dependencies(coverage_planner ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(coverage_ros_test test/nodes/coverage_ros_test.cpp src/ros/coverage_ros.cpp
    LINK roomba_coverage_planning roomba_node_common ROS)
  add_rostest(test/coverage/plan_coverage.test DEPENDENCIES coverage_planner roomba_sim)
endif()
