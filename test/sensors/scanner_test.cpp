// Scans in simulated time (scanner.h): the LDS preset's ranges in the lab's room, REP 117's
// infinities, the rate, the seeded noise, and the other robots seen.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::sensors {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

world::World labWorld(const std::string& sensors) {
  return world::parseWorld("sensors: " + sensors);  // the lab's 6.4 x 4.8 m room
}

TEST(Scanner, the_lds_sees_the_lab_room_walls_and_nothing_beyond_its_range) {
  Scanner scanner(world::parseWorld("room: {width: 6.4, height: 4.8}"));
  const auto& scans = scanner.scan(0, {{3.2, 2.4, 0}});
  ASSERT_EQ(scans.size(), 1u);
  const std::vector<float>& r = scans[0].ranges;
  ASSERT_EQ(r.size(), 360u);
  EXPECT_FLOAT_EQ(r[0], 3.2f);    // ahead: the right wall
  EXPECT_FLOAT_EQ(r[90], 2.4f);   // left: the top wall
  EXPECT_FLOAT_EQ(r[180], 3.2f);  // behind
  EXPECT_FLOAT_EQ(r[270], 2.4f);
  EXPECT_EQ(r[40], kInf);  // the corner, 4 m away: beyond 3.5 m (REP 117's no return)
}

TEST(Scanner, a_return_nearer_than_range_min_reads_minus_infinity) {
  Scanner scanner(labWorld("[{samples: 1, range_min: 0.5}]"));
  EXPECT_EQ(scanner.scan(0, {{6.0, 2.4, 0}})[0].ranges[0], -kInf);  // 0.4 m from the wall
  EXPECT_FLOAT_EQ(scanner.scan(1, {{5.8, 2.4, 0}})[0].ranges[0], 0.6f);
}

TEST(Scanner, the_mounting_pose_moves_and_turns_the_rays) {
  // 0.1 m forward on a robot facing +y, looking back: the bottom wall from y = 2.5.
  Scanner scanner(labWorld("[{samples: 1, x: 0.1, yaw: 3.141592653589793, range_max: 10}]"));
  EXPECT_FLOAT_EQ(scanner.scan(0, {{3.2, 2.4, M_PI / 2}})[0].ranges[0], 2.5f);
}

TEST(Scanner, each_sensor_scans_at_its_rate_in_simulated_time) {
  Scanner scanner(labWorld("[{preset: lds}, {preset: ir_bumper}]"));
  int lds = 0, ir = 0;
  const double step = 1.0 / 60;
  for (int s = 0; s < 120; ++s) {  // two simulated seconds
    for (const Scan& scan : scanner.scan(s * step, {{3.2, 2.4, 0}})) {
      (scan.sensor == 0 ? lds : ir) += 1;
      EXPECT_DOUBLE_EQ(scan.time, s * step);
      if (scan.sensor == 0) {
        EXPECT_EQ(s % 12, 0) << "5 Hz at 60 steps/s: every 12th step";
      }
    }
  }
  EXPECT_EQ(lds, 10);
  EXPECT_EQ(ir, 40);
  EXPECT_EQ(scanner.rays(), 10u * 360 + 40u * 6);
}

TEST(Scanner, noise_is_seeded_gaussian_and_stays_within_the_range) {
  const std::string spec =
      "[{samples: 2000, angle_min: -0.3, angle_max: 0.3, range_max: 10, "
      "noise_stddev: 0.05, seed: 4}]";
  Scanner a(labWorld(spec)), b(labWorld(spec));
  const std::vector<float> ra = a.scan(0, {{3.2, 2.4, M_PI / 2}})[0].ranges;
  EXPECT_EQ(ra, b.scan(0, {{3.2, 2.4, M_PI / 2}})[0].ranges);  // same seed, same scan
  double sum = 0, sum_sq = 0;
  const double increment = 0.6 / 1999;
  for (int k = 0; k < 2000; ++k) {
    const double truth = 2.4 / std::cos(-0.3 + k * increment);  // the top wall
    sum += ra[k] - truth;
    sum_sq += (ra[k] - truth) * (ra[k] - truth);
  }
  EXPECT_NEAR(sum / 2000, 0, 0.005);
  EXPECT_NEAR(std::sqrt(sum_sq / 2000), 0.05, 0.005);
  // Clamped into [range_min, range_max]: a wall at 2.4 m read by a 2.45 m sensor.
  Scanner c(
      labWorld("[{samples: 500, angle_min: 1.5707963, angle_max: 1.5707963, "
               "range_max: 2.45, noise_stddev: 0.5}]"));
  for (float r : c.scan(0, {{3.2, 2.4, 0}})[0].ranges) {
    EXPECT_GE(r, 0.12f);
    EXPECT_LE(r, 2.45f);
  }
}

TEST(Scanner, robots_see_each_other) {
  const world::World world = world::parseWorld(
      "sensors: [{samples: 1, range_max: 10}]\n"
      "robots:\n"
      "  - {name: a, initial_pose: {x: 1, y: 2.4}}\n"
      "  - {name: b, initial_pose: {x: 3, y: 2.4, theta: 3.141592653589793}}\n");
  Scanner scanner(world);
  const auto& scans = scanner.scan(0, {world.robots[0].initial_pose, world.robots[1].initial_pose});
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_FLOAT_EQ(scans[0].ranges[0], 1.83f);  // a sees b's disc
  EXPECT_FLOAT_EQ(scans[1].ranges[0], 1.83f);
}

}  // namespace
}  // namespace roomba_rrt::sensors
