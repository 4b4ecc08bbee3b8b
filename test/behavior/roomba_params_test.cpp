// The behaviour parameters: lab defaults, the YAML file, and errors that name the field.
#include <gtest/gtest.h>

#include "../common/hostile_yaml.h"
#include "roomba_rrt/behavior/roomba_params.h"

namespace roomba_rrt::behavior {
namespace {

std::string errorOf(const std::string& yaml) {
  try {
    parseRoombaParams(yaml, "test.yaml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(RoombaParams, the_defaults_are_the_lab_constants_in_ticks) {
  const RoombaParams p;
  EXPECT_EQ(p.ticks(p.move_forward_time), 180);
  EXPECT_EQ(p.ticks(p.move_in_spiral_time), 1200);
  EXPECT_EQ(p.ticks(p.go_back_time), 30);
  EXPECT_DOUBLE_EQ(p.sampleTime(), 1.0 / 60.0);
}

TEST(RoombaParams, the_config_file_holds_the_lab_constants) {
  const RoombaParams file = loadRoombaParams(ROOMBA_RRT_CONFIG_DIR "/roomba_behavior.yaml");
  const RoombaParams lab;
  EXPECT_EQ(file.move_forward_time, lab.move_forward_time);
  EXPECT_EQ(file.move_in_spiral_time, lab.move_in_spiral_time);
  EXPECT_EQ(file.go_back_time, lab.go_back_time);
  EXPECT_EQ(file.forward_speed, lab.forward_speed);
  EXPECT_EQ(file.backward_speed, lab.backward_speed);
  EXPECT_EQ(file.angular_speed, lab.angular_speed);
  EXPECT_EQ(file.initial_radius_spiral, lab.initial_radius_spiral);
  EXPECT_EQ(file.spiral_factor, lab.spiral_factor);
  EXPECT_EQ(file.rate, lab.rate);
}

TEST(RoombaParams, missing_keys_keep_their_defaults) {
  const RoombaParams p = parseRoombaParams("forward_speed: 0.3\n");
  EXPECT_EQ(p.forward_speed, 0.3);
  EXPECT_EQ(p.angular_speed, 0.5);
}

TEST(RoombaParams, errors_name_the_source_and_the_field) {
  EXPECT_EQ(errorOf("forward_sped: 0.3"), "test.yaml: forward_sped: is not a known parameter");
  EXPECT_EQ(errorOf("angular_speed: fast"), "test.yaml: angular_speed: must be a number");
  EXPECT_EQ(errorOf("angular_speed: 0"), "test.yaml: angular_speed: must be in (0, 100], got 0");
  EXPECT_EQ(errorOf("backward_speed: 0.1"),
            "test.yaml: backward_speed: must be in [-100, 0) (it drives backwards), got 0.1");
  EXPECT_EQ(errorOf("rate: .nan"), "test.yaml: rate: must be finite, got nan");
  EXPECT_EQ(errorOf("[1, 2]"), "test.yaml: the top level must be a map of parameters");
  EXPECT_EQ(errorOf("forward_speed: 0.3\nforward_speed: 0.4\n"),
            "test.yaml: forward_speed: is given twice (lines 1 and 2); a mapping holds one "
            "value per key");
}

// Issue 44, item 1: a behaviour config with aliases is refused at once, naming the line.
TEST(RoombaParams, anchors_and_aliases_are_refused_naming_the_line) {
  using roomba_rrt::test::aliasRefusal;
  EXPECT_EQ(errorOf("forward_speed: &s 0.3\n"), "test.yaml: " + aliasRefusal(1, 16));
  EXPECT_EQ(errorOf("rate: 10\n" + roomba_rrt::test::aliasBomb(9)),
            "test.yaml: " + aliasRefusal(2, 5));
  EXPECT_EQ(errorOf(roomba_rrt::test::kRecursiveAlias), "test.yaml: " + aliasRefusal(1, 7));
}

// Issue 11: a rate of 1e9 froze the node, 1e308 flooded /cmd_vel, 1e-300 died with a message
// naming no parameter; a time of 1e300 overflowed the tick count.
TEST(RoombaParams, values_outside_the_supported_ranges_are_named) {
  EXPECT_EQ(errorOf("rate: 1.0e9"), "test.yaml: rate: must be in [1, 1000] Hz, got 1e+09");
  EXPECT_EQ(errorOf("rate: 1.0e-300"), "test.yaml: rate: must be in [1, 1000] Hz, got 1e-300");
  EXPECT_EQ(errorOf("rate: 0.5"), "test.yaml: rate: must be in [1, 1000] Hz, got 0.5");
  EXPECT_EQ(errorOf("move_in_spiral_time: 1e300"),
            "test.yaml: move_in_spiral_time: must be in [0, 1e6] s, got 1e+300");
  EXPECT_EQ(errorOf("go_back_time: -1"), "test.yaml: go_back_time: must be in [0, 1e6] s, got -1");
  EXPECT_EQ(errorOf("forward_speed: 1000"),
            "test.yaml: forward_speed: must be in (0, 100], got 1000");
  EXPECT_EQ(errorOf("backward_speed: -1e200"),
            "test.yaml: backward_speed: must be in [-100, 0) (it drives backwards), got -1e+200");
  EXPECT_EQ(errorOf("spiral_factor: 1e4"),
            "test.yaml: spiral_factor: must be in [0, 1000], got 10000");
  EXPECT_EQ(errorOf("initial_radius_spiral: 2000"),
            "test.yaml: initial_radius_spiral: must be in (0, 1000], got 2000");
}

TEST(RoombaParams, the_range_limits_themselves_are_accepted) {
  EXPECT_EQ(errorOf("rate: 1"), "no error");
  EXPECT_EQ(errorOf("rate: 1000\nmove_in_spiral_time: 1e6\nforward_speed: 100"), "no error");
  EXPECT_EQ(parseRoombaParams("rate: 1000\nmove_in_spiral_time: 1e6").ticks(1e6), 1000000000L);
}

TEST(RoombaParams, an_unreadable_file_is_named) {
  EXPECT_THROW(loadRoombaParams("/nonexistent.yaml"), std::invalid_argument);
}

// Issue 11: a directory read as an empty file, so it silently gave the defaults.
TEST(RoombaParams, a_directory_is_refused_not_read_as_empty) {
  try {
    loadRoombaParams("/tmp");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "/tmp: cannot read the parameter file (not a regular file)");
  }
}

}  // namespace
}  // namespace roomba_rrt::behavior
