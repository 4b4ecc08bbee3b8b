# roomba_rrt_gtest(<target> <sources>... [LINK <libraries>...] [DEPENDS <targets>...] [ROS])
#
# A gtest unit test (catkin_add_gtest, run by ctest and scripts/test) linked with gtest_main and
# LINK, built after DEPENDS (executables it runs), with ROOMBA_RRT_CONFIG_DIR and
# ROOMBA_RRT_TEST_DIR pointing into the source tree, and ROOMBA_RRT_SHARED_MAPS at the real maps
# beside the repository (../shared/maps; test/common/shared_maps.h: a test skips, saying which map
# it wanted, when one is not there, and fails in CI). ROS: the test also uses ROS headers, roscpp
# and this package's generated messages (still no master: those tests are rostests).
function(roomba_rrt_gtest target)
  cmake_parse_arguments(ARG "ROS" "" "LINK;DEPENDS" ${ARGN})
  if(NOT CATKIN_ENABLE_TESTING)
    return()
  endif()
  catkin_add_gtest(${target} ${ARG_UNPARSED_ARGUMENTS})
  if(NOT TARGET ${target})
    return()  # no gtest
  endif()
  target_link_libraries(${target} ${ARG_LINK} gtest_main)
  target_compile_definitions(${target} PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${PROJECT_SOURCE_DIR}/config"
    ROOMBA_RRT_TEST_DIR="${PROJECT_SOURCE_DIR}/test"
    ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
  if(ARG_DEPENDS)
    add_dependencies(${target} ${ARG_DEPENDS})
  endif()
  if(ARG_ROS)
    target_include_directories(${target} PRIVATE ${catkin_INCLUDE_DIRS})
    target_link_libraries(${target} ${catkin_LIBRARIES})
    add_dependencies(${target} ${${PROJECT_NAME}_EXPORTED_TARGETS})
  endif()
endfunction()
