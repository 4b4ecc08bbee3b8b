# Range sensors (doc/simulation.md, "Sensors"): what a world file's `sensors:` describes and its
# rules (roomba_sensor_spec, which the world library links to read and check world files), and
# the ray casting and scan schedule over a world (roomba_sensors, which roomba_sim uses).
# ROS-free.

add_library(roomba_sensor_spec src/sensors/range_sensor.cpp)
target_include_directories(roomba_sensor_spec PUBLIC ${PROJECT_SOURCE_DIR}/include)

add_library(roomba_sensors src/sensors/blocked_bits.cpp src/sensors/ray_cast.cpp
  src/sensors/scanner.cpp)
target_include_directories(roomba_sensors PUBLIC ${PROJECT_SOURCE_DIR}/include)
target_link_libraries(roomba_sensors PUBLIC roomba_sensor_spec roomba_world)
target_compile_options(roomba_sensors PRIVATE -fno-math-errno)

if(CATKIN_ENABLE_TESTING)
  roomba_rrt_gtest(sensors_test test/sensors/blocked_bits_test.cpp test/sensors/ray_cast_test.cpp
    test/sensors/sensor_spec_test.cpp test/sensors/scanner_test.cpp LINK roomba_sensors)
endif()

# Google Benchmark (libbenchmark-dev): rays per second, the lidars' cost per simulator step.
find_package(benchmark QUIET)
if(benchmark_FOUND)
  add_executable(sensor_bench bench/sensor_bench.cpp)
  target_link_libraries(sensor_bench roomba_sensors roomba_sim_core benchmark::benchmark)
  target_compile_definitions(sensor_bench PRIVATE
    ROOMBA_RRT_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config"
    ROOMBA_RRT_SHARED_MAPS="${PROJECT_SOURCE_DIR}/../shared/maps")
endif()
