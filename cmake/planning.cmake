# Planning: the ROS-free RRT library, its command-line tools, unit tests and benchmark.
# (The rrt_planner node and its rostest live in their own section at the end of this file.)

add_library(rrt_planning
  # the planning query and what every planner shares (include/roomba_rrt/planning/)
  src/planning/densify.cpp
  src/planning/free_point_near.cpp
  src/planning/grid_regions.cpp
  src/planning/path_smoothing.cpp
  src/planning/plan_result.cpp
  src/planning/planner.cpp
  src/planning/planner_options.cpp
  src/planning/problem.cpp
  src/planning/stop_condition.cpp
  src/planning/tree.cpp
  src/planning/validate.cpp
  # the planners (planning/planners/)
  src/planning/planners/region_astar.cpp
  src/planning/planners/rrt.cpp
  src/planning/planners/rrt_connect.cpp
  src/planning/planners/rrt_star.cpp
  # the nearest-neighbour index and its allocator (planning/nearest_neighbors/)
  src/planning/nearest_neighbors/brute_force_nearest_neighbors.cpp
  src/planning/nearest_neighbors/grid_nearest_neighbors.cpp
  src/planning/nearest_neighbors/nearest_neighbors.cpp
  # the lab's pieces: MATLAB's random stream, the scenarios file, Monte Carlo (planning/lab/)
  src/planning/lab/monte_carlo.cpp
  src/planning/lab/scenarios.cpp
)
target_include_directories(rrt_planning PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(rrt_planning PUBLIC roomba_geometry yaml-cpp)

# A world (its room, furniture, map and robot) as a planning problem: above both the world and
# the planning library, which knows neither files nor robots.
add_library(roomba_world_planning src/world_planning/room_problem.cpp)
target_link_libraries(roomba_world_planning PUBLIC rrt_planning roomba_world)

find_package(Threads REQUIRED)

# rrt_monte_carlo: the lab's monteCarloRRT statistics (no ROS master needed).
add_executable(rrt_monte_carlo src/tools/rrt_monte_carlo.cpp)
target_link_libraries(rrt_monte_carlo roomba_tools Threads::Threads)

# rrt_plot: draws a plan (bounds, obstacles, tree, path) into a PNG with Cairo.
add_executable(rrt_plot src/tools/rrt_plot.cpp)
target_link_libraries(rrt_plot roomba_tools)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(planning_core_test test/planning/geometry_test.cpp
    test/planning/matlab_random_test.cpp test/planning/nearest_neighbors_test.cpp
    test/planning/rrt_test.cpp test/planning/algorithms_test.cpp test/planning/validate_test.cpp
    test/planning/robustness_test.cpp test/planning/room_test.cpp
    test/planning/map_planning_test.cpp test/planning/densify_test.cpp
    test/planning/free_space_sampler_test.cpp test/planning/plan_random_test.cpp
    test/planning/region_astar_test.cpp
    LINK roomba_world_planning)
endif()

# planning_bench: time per solved query (a-d) and iterations/s on a 10^6-node tree.
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(planning_bench bench/planning_bench.cpp)
  target_link_libraries(planning_bench rrt_planning benchmark::benchmark)
  target_compile_definitions(planning_bench PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")
endif()

# --- rrt_planner node (owned by the node helper) ---
# The ROS adapter of the planning library: the rrt_planner node (service ~plan_path, rviz
# markers on ~tree, ~path), its rostests, and the service round-trip benchmark client.
add_executable(rrt_planner src/nodes/rrt_planner_node.cpp src/ros/rrt_planner.cpp src/ros/planner_ros.cpp
  src/ros/make_plan_ros.cpp
  src/ros/plan_slots.cpp)
target_link_libraries(rrt_planner roomba_world_planning roomba_node_common)
add_dependencies(rrt_planner ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

add_executable(plan_path_bench bench/plan_path_bench.cpp)
target_include_directories(plan_path_bench PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(plan_path_bench ${catkin_LIBRARIES})
add_dependencies(plan_path_bench ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

# Fairness: ordinary requests' latency while eight clients hammer the node with long plans.
add_executable(fairness_probe bench/fairness_probe.cpp)
target_include_directories(fairness_probe PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(fairness_probe ${catkin_LIBRARIES})
add_dependencies(fairness_probe ${${PROJECT_NAME}_EXPORTED_TARGETS})

# A 10^8-cell map over ROS: rrt_planner serving make_plan on a 100 MB /map.
add_executable(big_map_probe bench/big_map_probe.cpp)
target_include_directories(big_map_probe PRIVATE src/ros ${catkin_INCLUDE_DIRS})
target_link_libraries(big_map_probe roomba_node_common ${catkin_LIBRARIES})
target_compile_definitions(big_map_probe PRIVATE
  ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
add_dependencies(big_map_probe ${${PROJECT_NAME}_EXPORTED_TARGETS})

if(CATKIN_ENABLE_TESTING)
  # rostests through a real master; each .test starts the node and one gtest client node.
  foreach(planner_node_test
      plan_path_service:rrt_planner_service_test
      concurrent_clients:rrt_planner_concurrency_test
      animation:rrt_planner_animation_test
      hostile_requests:rrt_planner_hostile_test
      room:rrt_planner_room_test
      make_plan:rrt_planner_make_plan_test)
    string(REPLACE ":" ";" planner_node_test ${planner_node_test})
    list(GET planner_node_test 0 launch_name)
    list(GET planner_node_test 1 test_target)
    add_rostest_gtest(${test_target} test/nodes/${launch_name}.test
      test/nodes/${launch_name}_test.cpp test/nodes/test_support.cpp)
    target_include_directories(${test_target} PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(${test_target} ${catkin_LIBRARIES})
    add_dependencies(${test_target} rrt_planner
      ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})
  endforeach()
  # Who gets a planning thread when all are taken (ROS-free).
  roomba_rrt_gtest(plan_slots_test test/nodes/plan_slots_test.cpp src/ros/plan_slots.cpp)
endif()
