# The command-line tools' own library: argument parsing (tool_arguments) and PNG drawing (drawing),
# shared by rrt_monte_carlo, rrt_plot, roomba_coverage and roomba_nav_eval (declared with their
# parts). The source tree's config/ is baked in here, for the tools' default files, and nowhere
# in the core libraries.

add_library(roomba_tools STATIC src/tools/tool_arguments.cpp src/tools/drawing.cpp)
target_include_directories(roomba_tools PUBLIC ${PROJECT_SOURCE_DIR}/src/tools)
target_link_libraries(roomba_tools PUBLIC roomba_world_planning roomba_sim_core PkgConfig::CAIRO)
target_compile_definitions(roomba_tools PUBLIC ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config")

if(CATKIN_ENABLE_TESTING)
  # The shared flags and statistics, and roomba_coverage's arguments and statistics.
  roomba_rrt_gtest(tools_test test/tools/tools_test.cpp src/tools/coverage_arguments.cpp
    src/tools/coverage_statistics.cpp LINK roomba_tools)
endif()

if(CATKIN_ENABLE_TESTING)
  # Every executable answers --help (exit 0, without a master); a missing maps folder is named.
  add_test(NAME help_test COMMAND bash ${PROJECT_SOURCE_DIR}/test/integration/help_test.bash)
  set_tests_properties(help_test PROPERTIES ENVIRONMENT "RR_DEVEL=${CATKIN_DEVEL_PREFIX}"
    TIMEOUT 300)
endif()
