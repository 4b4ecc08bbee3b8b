# libFuzzer harnesses (test/fuzz/*_fuzzer.cpp), built only with ROOMBA_RRT_SANITIZE=ON; seed
# corpora in test/fuzz/corpus/<harness>/. scripts/fuzz builds and runs them.
if(ROOMBA_RRT_SANITIZE)
  add_custom_target(fuzzers)
  function(roomba_rrt_fuzzer name)
    add_executable(${name} EXCLUDE_FROM_ALL test/fuzz/${name}.cpp ${ARGN})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
    add_dependencies(fuzzers ${name})
  endfunction()

  roomba_rrt_fuzzer(world_fuzzer)
  target_link_libraries(world_fuzzer roomba_sim_core)
  roomba_rrt_fuzzer(map_fuzzer)
  target_link_libraries(map_fuzzer roomba_geometry)
  roomba_rrt_fuzzer(scan_fuzzer)
  target_link_libraries(scan_fuzzer roomba_mapping)
  roomba_rrt_fuzzer(roomba_params_fuzzer)
  target_link_libraries(roomba_params_fuzzer roomba_behavior_core)
  roomba_rrt_fuzzer(tree_fuzzer)
  target_link_libraries(tree_fuzzer roomba_behavior_core)
  roomba_rrt_fuzzer(groot2_fuzzer)
  target_link_libraries(groot2_fuzzer roomba_behavior_core)
  # The planning library uses GCC's vector built-ins (__builtin_shuffle, target_clones) that clang
  # cannot compile: rrt_planning_sanitized is rrt_planning with those files compiled by g++
  # (-O2, not instrumented: ASan still catches their wild accesses as SEGVs, not their overflows
  # inside the heap), everything else by clang with the sanitizers.
  set(RR_GCC_ONLY_SOURCES src/planning/nearest_neighbors/grid_nearest_neighbors.cpp)
  get_target_property(RR_PLANNING_SOURCES rrt_planning SOURCES)
  list(REMOVE_ITEM RR_PLANNING_SOURCES ${RR_GCC_ONLY_SOURCES})
  set(RR_GCC_OBJECTS)
  foreach(source ${RR_GCC_ONLY_SOURCES})
    get_filename_component(stem ${source} NAME_WE)
    set(object ${CMAKE_CURRENT_BINARY_DIR}/gcc_objects/${stem}.o)
    add_custom_command(OUTPUT ${object}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/gcc_objects
      COMMAND g++ -std=c++17 -O2 -g -fPIC -I${PROJECT_SOURCE_DIR}/include
              -c ${PROJECT_SOURCE_DIR}/${source} -o ${object}
      DEPENDS ${PROJECT_SOURCE_DIR}/${source} IMPLICIT_DEPENDS CXX ${PROJECT_SOURCE_DIR}/${source}
      COMMENT "g++ (GCC-only vector code) ${source}")
    list(APPEND RR_GCC_OBJECTS ${object})
  endforeach()
  add_library(rrt_planning_sanitized STATIC EXCLUDE_FROM_ALL ${RR_PLANNING_SOURCES}
    ${RR_GCC_OBJECTS})
  target_include_directories(rrt_planning_sanitized PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_link_libraries(rrt_planning_sanitized PUBLIC roomba_geometry roomba_world yaml-cpp)

  # The node's own request conversion (src/ros/planner_ros.cpp) in front of the library.
  roomba_rrt_fuzzer(plan_path_fuzzer src/ros/planner_ros.cpp src/ros/make_plan_ros.cpp)
  target_include_directories(plan_path_fuzzer PRIVATE include ${catkin_INCLUDE_DIRS})
  target_link_libraries(plan_path_fuzzer rrt_planning_sanitized ${catkin_LIBRARIES})
  target_compile_definitions(plan_path_fuzzer PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")
  add_dependencies(plan_path_fuzzer ${${PROJECT_NAME}_EXPORTED_TARGETS})

  # The coverage_planner node's own request conversion (src/ros/coverage_ros.cpp) and plan.
  roomba_rrt_fuzzer(plan_coverage_fuzzer src/ros/coverage_ros.cpp)
  target_include_directories(plan_coverage_fuzzer PRIVATE include ${catkin_INCLUDE_DIRS})
  target_link_libraries(plan_coverage_fuzzer roomba_coverage_planning ${catkin_LIBRARIES})
  target_compile_definitions(plan_coverage_fuzzer PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")
  add_dependencies(plan_coverage_fuzzer ${${PROJECT_NAME}_EXPORTED_TARGETS})

  # A map as it arrives on /map: the nodes' conversion (src/ros/map_messages.cpp), then what
  # rrt_planner and coverage_planner build from it.
  roomba_rrt_fuzzer(map_message_fuzzer src/ros/map_messages.cpp)
  target_include_directories(map_message_fuzzer PRIVATE include ${catkin_INCLUDE_DIRS})
  target_link_libraries(map_message_fuzzer rrt_planning_sanitized ${catkin_LIBRARIES})

  # The planning unit tests on that library (scripts/fuzz --unit).
  if(TARGET planning_core_test)
    get_target_property(RR_PLANNING_TESTS planning_core_test SOURCES)
    add_executable(planning_core_test_sanitized EXCLUDE_FROM_ALL ${RR_PLANNING_TESTS}
      src/world_planning/room_problem.cpp)
    target_link_libraries(planning_core_test_sanitized rrt_planning_sanitized gtest gtest_main)
    get_target_property(RR_PLANNING_TEST_DEFINITIONS planning_core_test COMPILE_DEFINITIONS)
    target_compile_definitions(planning_core_test_sanitized PRIVATE
      ${RR_PLANNING_TEST_DEFINITIONS})
  endif()
endif()
