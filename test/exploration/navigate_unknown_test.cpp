// Driving to goals in a home the robot has never seen (exploration/navigate_unknown.h): through
// roomba_nav_eval's loop (the simulator, the lidar, a fresh map per goal), as a user runs it with
// --unknown, and the goals it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "nav_eval_run.h"
#include "roomba_rrt/exploration/navigate_unknown.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::exploration {
namespace {

const std::string kTree = ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml";

tools::NavEvalReport unknownGoals(const std::string& world_file, int goals, std::uint32_t seed) {
  tools::NavEvalOptions options;
  options.goals = goals;
  options.seed = seed;
  options.unknown = true;
  return tools::evaluateNavigation(world::loadWorld(world_file), kTree, options);
}

TEST(NavigateUnknown, reaches_random_goals_in_a_furnished_room_it_has_never_seen_without_a_bump) {
  const tools::NavEvalReport r =
      unknownGoals(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml", 30, 2);
  EXPECT_GE(r.reached_pct, 96.0);  // seed 2: all 30 (200 of 200 in doc/navigation.md)
  EXPECT_EQ(r.bumps, 0);
  EXPECT_LE(r.mean_length_ratio, 1.2);
  // Some goal was planned again on the way: the scans showed its first path blocked.
  int replanned = 0;
  for (const tools::GoalRun& run : r.runs) replanned += run.plans > 1;
  EXPECT_GT(replanned, 0);
  // Deterministic: the same seed drives the same way.
  const tools::NavEvalReport again =
      unknownGoals(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml", 5, 2);
  for (std::size_t i = 0; i < again.runs.size(); ++i) {
    EXPECT_EQ(again.runs[i].driven_m, r.runs[i].driven_m) << "goal " << i;
  }
}

TEST(NavigateUnknown, finds_the_door_to_a_goal_in_the_room_it_cannot_see) {
  const world::World world = world::loadWorld(ROOMBA_RRT_TEST_DIR "/tools/worlds/two_rooms.yaml");
  sim::Simulator simulator(world);
  sensors::Scanner scanner(world);
  double clock = 0;
  // Behind the wall, past the 0.5 m door; the wall's far part is out of the lidar's sight.
  const tools::GoalRun run =
      tools::driveUnknown(simulator, scanner, kTree, {6.5, 3.0, 0.0}, 1, 120, clock);
  EXPECT_TRUE(run.reached) << run.message;
  EXPECT_EQ(run.bumps, 0);
  EXPECT_GT(run.plans, 1) << "the first path went through the wall it had not seen whole";
}

TEST(NavigateUnknown, refuses_a_goal_that_is_not_finite_or_too_far_naming_the_field) {
  world::World world = world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  behavior::RoombaParams params;
  NavigateUnknown nav(world.robot(), params, 1, 0.0, kTree);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [goal, field] : {std::pair{robot::Pose2D{nan, 1, 0}, "goal.x"},
                                    std::pair{robot::Pose2D{1, 1e308, 0}, "goal"},
                                    std::pair{robot::Pose2D{1, 1, INFINITY}, "goal.theta"}}) {
    try {
      nav.setGoal(goal);
      ADD_FAILURE() << "accepted a goal that should be refused (" << field << ")";
    } catch (const util::InvalidInput& e) {
      EXPECT_EQ(e.field(), field);
    }
  }
  EXPECT_EQ(nav.outcome(), navigation::GoalOutcome::kNone);  // nothing was taken
  // Without a scan the robot stands and waits.
  nav.setGoal({2, 2, 0});
  const robot::Velocity v = nav.tick(0, {}, world.robot().initial_pose, 0);
  EXPECT_EQ(v.v, 0);
  EXPECT_EQ(v.w, 0);
  EXPECT_EQ(nav.outcome(), navigation::GoalOutcome::kActive);
}

}  // namespace
}  // namespace roomba_rrt::exploration
