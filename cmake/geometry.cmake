# The plane geometry shared by the simulator (contact, bumper) and the planner (collision checks),
# and the maps both use: occupancy grids (occupancy_grid) read from map_server files (map_file;
# map_image: netpbm read by hand, PNG by libpng, to the bytes map_server's SDL2_image gives). A
# small ROS-free library and its tests.

pkg_check_modules(LIBPNG REQUIRED IMPORTED_TARGET libpng)

add_library(roomba_geometry src/geometry/geometry.cpp src/geometry/occupancy_grid.cpp
  src/geometry/distance_transform.cpp src/geometry/clearance_map.cpp
  src/geometry/free_tiles.cpp
  src/geometry/map_file.cpp src/geometry/map_image.cpp)
target_include_directories(roomba_geometry PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_geometry PRIVATE yaml-cpp PkgConfig::LIBPNG)

if(CATKIN_ENABLE_TESTING)
  # The map tests write their PNGs with libpng.
  roomba_rrt_gtest(geometry_test test/geometry/geometry_test.cpp
    test/geometry/occupancy_grid_test.cpp test/geometry/map_file_test.cpp
    test/geometry/clearance_map_test.cpp test/geometry/map_image_test.cpp
    LINK roomba_geometry PkgConfig::LIBPNG)
endif()
