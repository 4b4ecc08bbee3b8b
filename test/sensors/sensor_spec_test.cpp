// The `sensors:` section of a world file (world_file.h, range_sensor.h): the LDS preset when it
// names none, `sensors: []` for none, presets and overrides, named robots, and the refusals,
// each naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "roomba_rrt/sensors/range_sensor.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::sensors {
namespace {

using world::parseWorld;

/// The message parseWorld throws for `yaml` ("" when it reads it).
std::string errorFor(const std::string& yaml) {
  std::string message;
  EXPECT_THROW(
      try { parseWorld(yaml, "test.yaml"); } catch (const util::InvalidInput& e) {
        message = e.what();
        throw;
      },
      util::InvalidInput)
      << yaml;
  return message;
}

TEST(SensorSpec, a_world_naming_no_sensors_gets_the_lds_preset) {
  const world::World world = parseWorld("room: {width: 6.4, height: 4.8}");
  ASSERT_EQ(world.robot().sensors.size(), 1u);
  const RangeSensorSpec& lds = world.robot().sensors[0];
  EXPECT_EQ(lds.name, "scan");
  EXPECT_EQ(lds.frame, "base_scan");
  EXPECT_EQ(lds.samples, 360);
  EXPECT_DOUBLE_EQ(lds.range_min, 0.12);
  EXPECT_DOUBLE_EQ(lds.range_max, 3.5);
  EXPECT_DOUBLE_EQ(lds.rate, 5);
  EXPECT_DOUBLE_EQ(lds.angleIncrement(), M_PI / 180);
  EXPECT_EQ(lds.angle_min, 0);  // straight ahead, as hls_lfcd_lds_driver's first sample
  EXPECT_DOUBLE_EQ(lds.angle_max, 2 * M_PI * 359 / 360);
  EXPECT_EQ(lds.noise_stddev, 0);
}

TEST(SensorSpec, an_empty_list_turns_them_off) {
  EXPECT_TRUE(parseWorld("sensors: []").robot().sensors.empty());
}

TEST(SensorSpec, a_slow_simulator_slows_the_default_preset_only) {
  EXPECT_DOUBLE_EQ(parseWorld("step: 0.5\nrobot: {max_linear_speed: 0.1}").robot().sensors[0].rate,
                   2);
  EXPECT_NE(errorFor("step: 0.5\nrobot: {max_linear_speed: 0.1}\nsensors: [{preset: lds}]")
                .find("sensors[0].rate: must be in (0, 2] Hz"),
            std::string::npos);
}

TEST(SensorSpec, presets_take_overrides_and_names_give_frames) {
  const world::World world = parseWorld(
      "sensors:\n"
      "  - {preset: ir_bumper}\n"
      "  - {name: front, angle_min: -1, angle_max: 1, samples: 90, range_max: 8, rate: 10,\n"
      "     noise_stddev: 0.01, seed: 7, x: 0.1, y: 0.02, yaw: 0.5}\n");
  ASSERT_EQ(world.robot().sensors.size(), 2u);
  const RangeSensorSpec& ir = world.robot().sensors[0];
  EXPECT_EQ(ir.name, "ir_bumper");
  EXPECT_EQ(ir.frame, "base_ir_bumper");
  EXPECT_EQ(ir.samples, 6);
  EXPECT_DOUBLE_EQ(ir.range_max, 0.15);
  EXPECT_DOUBLE_EQ(ir.mount.x, 0.17);  // the front of the bumper
  EXPECT_DOUBLE_EQ(ir.angle_min, -70 * M_PI / 180);
  EXPECT_DOUBLE_EQ(ir.angle_max, 70 * M_PI / 180);
  EXPECT_EQ(ir.range_min, 0);
  EXPECT_DOUBLE_EQ(ir.rate, 20);
  const RangeSensorSpec& front = world.robot().sensors[1];
  EXPECT_EQ(front.name, "front");
  EXPECT_EQ(front.frame, "base_front");
  EXPECT_EQ(front.samples, 90);
  EXPECT_DOUBLE_EQ(front.range_min, 0.12);  // the rest from the lds preset
  EXPECT_DOUBLE_EQ(front.range_max, 8);
  EXPECT_EQ(front.seed, 7u);
  EXPECT_DOUBLE_EQ(front.mount.theta, 0.5);
}

TEST(SensorSpec, named_robots_share_the_top_level_sensors_unless_they_name_their_own) {
  const world::World world = parseWorld(
      "sensors: [{preset: ir_bumper}]\n"
      "robots:\n"
      "  - {name: a, initial_pose: {x: 1, y: 1}}\n"
      "  - {name: b, initial_pose: {x: 3, y: 1}, sensors: [{preset: lds}, {preset: ir_bumper}]}\n"
      "  - {name: c, initial_pose: {x: 5, y: 1}, sensors: []}\n");
  ASSERT_EQ(world.robots.size(), 3u);
  ASSERT_EQ(world.robots[0].sensors.size(), 1u);
  EXPECT_EQ(world.robots[0].sensors[0].name, "ir_bumper");
  EXPECT_EQ(world.robots[1].sensors.size(), 2u);
  EXPECT_TRUE(world.robots[2].sensors.empty());
}

TEST(SensorSpec, bad_sensors_are_refused_naming_the_field) {
  const auto refuses = [](const std::string& sensor, const std::string& message) {
    const std::string error = errorFor("sensors: [" + sensor + "]");
    EXPECT_NE(error.find(message), std::string::npos) << sensor << " -> " << error;
  };
  refuses("{samples: 0}", "test.yaml: sensors[0].samples: must be in [1, 100000], got 0");
  refuses("{samples: 1.5}", "sensors[0].samples: must be a whole number");
  refuses("{range_min: 2, range_max: 2}",
          "sensors[0].range_max: must be greater than range_min (2), got 2");
  refuses("{range_min: -1}", "sensors[0].range_min: must be in [0, 1000] m, got -1");
  refuses("{rate: 100}", "sensors[0].rate: must be in (0, 60] Hz");
  refuses("{noise_stddev: .nan}", "sensors[0].noise_stddev: must be in [0, 100] m, got nan");
  refuses("{x: 0.15, y: 0.1}", "sensors[0].x: (0.15, 0.1) is outside the robot's disc");
  refuses("{yaw: .inf}", "sensors[0].yaw: must be finite, got inf");
  refuses("{angle_min: 1, angle_max: 0}", "sensors[0].angle_max: must be in [1, ");
  refuses("{name: 'a/b'}", "sensors[0].name: must start with a letter");
  refuses("{preset: kinect}", "sensors[0].preset: must be lds or ir_bumper, got 'kinect'");
  refuses("{range: 3}", "sensors[0].range: is not a known parameter");
  refuses("{preset: lds}, {preset: lds}", "sensors[1].name: repeats 'scan'");
  std::string eleven;  // 1.1 M rays per scan
  for (char name = 'a'; name <= 'k'; ++name) {
    eleven += std::string(eleven.empty() ? "" : ", ") + "{samples: 100000, name: " + name + "}";
  }
  refuses(eleven, "sensors: have 1100000 samples per scan over all robots; at most 1000000");
  EXPECT_NE(errorFor("sensors: {preset: lds}").find("sensors: must be a list"), std::string::npos);
  EXPECT_NE(errorFor("robots:\n  - {name: a, initial_pose: {x: 1, y: 1}, sensors: [{rate: 0}]}")
                .find("robots[0].sensors[0].rate: must be in (0, 60] Hz"),
            std::string::npos);
}

}  // namespace
}  // namespace roomba_rrt::sensors
