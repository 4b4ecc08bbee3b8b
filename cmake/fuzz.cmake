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
  roomba_rrt_fuzzer(roomba_params_fuzzer)
  target_link_libraries(roomba_params_fuzzer roomba_behavior_core)
  roomba_rrt_fuzzer(tree_fuzzer)
  target_link_libraries(tree_fuzzer roomba_behavior_core)
  # The node's own request conversion (src/nodes/planner_ros.cpp) in front of the library.
  roomba_rrt_fuzzer(plan_path_fuzzer src/nodes/planner_ros.cpp)
  target_include_directories(plan_path_fuzzer PRIVATE include ${catkin_INCLUDE_DIRS})
  target_link_libraries(plan_path_fuzzer rrt_planning ${catkin_LIBRARIES})
  add_dependencies(plan_path_fuzzer ${${PROJECT_NAME}_EXPORTED_TARGETS})
endif()
