# Benchmarks and the peer comparison (scripts/bench runs them all and prints one table).
#
# Each benchmark is built only when what it needs is installed (Google Benchmark:
# libbenchmark-dev; OMPL 1.5: libompl-dev, a benchmark-only dependency). planning_bench, sim_bench
# and the probes plan_path_bench, sim_rtf_probe and nav_latency_probe are part of the default
# build; behavior_bench, ompl_comparison, map_comparison and map_load_bench are built only on
# request. This builds them all:
#   cmake --build <build-dir> --target benchmarks
# The executables land in lib/roomba_rrt/ of the devel space, like the nodes.

find_package(benchmark QUIET)
find_package(ompl QUIET)

add_custom_target(benchmarks)

# --- OMPL, through its CMake config -----------------------------------------------------------
# Debian's ompl.pc is unusable as is (`-L_link_dirs-NOTFOUND`, and `-std=c++14` against our
# C++17); omplConfig.cmake gives clean variables. Its include list also names /usr/include,
# which must never become an explicit -I/-isystem (it breaks #include_next in libstdc++).
if(OMPL_FOUND)
  set(RR_OMPL_INCLUDE_DIRS ${OMPL_INCLUDE_DIRS})
  list(REMOVE_ITEM RR_OMPL_INCLUDE_DIRS /usr/include)
  list(FILTER RR_OMPL_INCLUDE_DIRS EXCLUDE REGEX "NOTFOUND")
  set(RR_OMPL_LIBRARIES ${OMPL_LIBRARIES})
  list(FILTER RR_OMPL_LIBRARIES EXCLUDE REGEX "NOTFOUND")
  message(STATUS "roomba_rrt benchmarks: OMPL ${OMPL_VERSION} found (${OMPL_INCLUDE_DIR})")
else()
  message(STATUS "roomba_rrt benchmarks: OMPL not found (libompl-dev); ompl_comparison skipped")
endif()
if(NOT benchmark_FOUND)
  message(STATUS "roomba_rrt benchmarks: Google Benchmark not found (libbenchmark-dev)")
endif()

# --- RRT against OMPL's RRT -------------------------------------------------------------------
if(OMPL_FOUND AND TARGET rrt_planning)
  # rr_ompl_benchmark(TARGET SOURCES...): a comparison with OMPL in one process (bench/ompl_lab.h).
  function(rr_ompl_benchmark target)
    add_executable(${target} EXCLUDE_FROM_ALL ${ARGN})
    target_include_directories(${target} PRIVATE include)
    target_include_directories(${target} SYSTEM PRIVATE ${RR_OMPL_INCLUDE_DIRS})
    target_link_libraries(${target} PRIVATE roomba_world_planning ${RR_OMPL_LIBRARIES})
    add_dependencies(benchmarks ${target})
  endfunction()

  # The lab's scenarios, the growth rows and the furnished room.
  rr_ompl_benchmark(ompl_comparison bench/ompl_comparison.cpp)
  target_compile_definitions(ompl_comparison PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")
  # The same on the shared real maps (issue 17), against the disc's shortest path.
  rr_ompl_benchmark(map_comparison bench/map_comparison.cpp bench/disc_lattice.cpp
    bench/grid_astar.cpp)
  target_compile_definitions(map_comparison PRIVATE
    ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
endif()

# --- loading and inflating a large map (issue 17): needs neither OMPL nor Google Benchmark ------
if(TARGET roomba_geometry)
  add_executable(map_load_bench EXCLUDE_FROM_ALL bench/map_load_bench.cpp)
  target_include_directories(map_load_bench PRIVATE include)
  target_link_libraries(map_load_bench PRIVATE rrt_planning)
  target_compile_definitions(map_load_bench PRIVATE
    ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
  add_dependencies(benchmarks map_load_bench)
endif()

# --- Groot2 monitoring's cost per tick of roomba_bt (issue 46): needs only ZeroMQ ---------------
if(TARGET roomba_bt_groot2)
  add_executable(groot2_bench EXCLUDE_FROM_ALL bench/groot2_bench.cpp)
  target_link_libraries(groot2_bench PRIVATE roomba_bt_groot2 PkgConfig::ZMQ)
  add_dependencies(benchmarks groot2_bench)
endif()

# --- the other parts' benchmarks (declared in their own fragments) ----------------------------
# `benchmarks` builds them too, plus the tools scripts/bench runs (the nodes it measures).
foreach(target IN ITEMS planning_bench behavior_bench sim_bench sensor_bench sim_rtf_probe
                        plan_path_bench
                        rrt_monte_carlo roomba_sim roomba_fsm rrt_planner roomba_bt
                        nav_latency_probe fairness_probe big_map_probe coverage_bench
                        mapping_bench)
  if(TARGET ${target})
    add_dependencies(benchmarks ${target})
  endif()
endforeach()

# The A* peer of map_comparison (bench/grid_astar.h) is tested like the library: its rows are
# only as right as it is.
roomba_rrt_gtest(grid_astar_test test/bench/grid_astar_test.cpp bench/grid_astar.cpp
  LINK roomba_geometry)
if(TARGET grid_astar_test)
  target_include_directories(grid_astar_test PRIVATE bench)
endif()
