// The pose a tick reads over ROS is a step old: PosePredictor drives it forward along the
// commands sent since, exactly as the simulator moves the robot, and without latency it is the
// pose seen.
#include <gtest/gtest.h>

#include <cmath>

#include "roomba_rrt/navigation/pose_predictor.h"
#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::navigation {
namespace {

constexpr double kRate = 60;

TEST(PosePredictor, without_latency_the_pose_seen_is_the_pose) {
  PosePredictor predictor(0, kRate);
  EXPECT_EQ(predictor.latency_ticks(), 0);
  predictor.sent({0.5, 1.0});
  const robot::Pose2D p = predictor.predict({1, 2, 0.3});
  EXPECT_DOUBLE_EQ(p.x, 1);
  EXPECT_DOUBLE_EQ(p.y, 2);
  EXPECT_DOUBLE_EQ(p.theta, 0.3);
}

TEST(PosePredictor, drives_the_last_commands_as_the_simulator_does) {
  PosePredictor predictor(2 / kRate, kRate);  // two ticks
  ASSERT_EQ(predictor.latency_ticks(), 2);
  const robot::Velocity older{-0.1, 0}, turn{0.5, 1.0}, straight{0.5, 0};
  predictor.sent(older);  // three ticks ago: already in the pose seen
  predictor.sent(turn);
  predictor.sent(straight);
  const robot::Pose2D seen{1, 2, 0.3};
  const robot::Pose2D expected =
      robot::integrateArc(robot::integrateArc(seen, turn, 1 / kRate), straight, 1 / kRate);
  const robot::Pose2D p = predictor.predict(seen);
  EXPECT_DOUBLE_EQ(p.x, expected.x);
  EXPECT_DOUBLE_EQ(p.y, expected.y);
  EXPECT_DOUBLE_EQ(p.theta, expected.theta);
  EXPECT_GT(p.x, seen.x + 0.015);  // about 2 × 0.5 m/s / 60 Hz ahead, not backwards
}

TEST(PosePredictor, refuses_a_latency_it_cannot_mean_naming_it) {
  for (double bad : {-0.01, 1.5, std::nan(""), double{INFINITY}}) {
    try {
      PosePredictor(bad, kRate);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const util::InvalidInput& e) {
      EXPECT_EQ(e.field(), "pose_latency");
    }
  }
  EXPECT_THROW(PosePredictor(0.1, 0), util::InvalidInput);
}

}  // namespace
}  // namespace roomba_rrt::navigation
