// Navigation trees end to end without ROS: NavBt on the simulator in the furnished room, with the
// in-process planner (inline, deterministic). The goal is reached within tolerance without a
// bump, an unreachable goal is aborted with a reason, a new goal preempts, a cancel stops, a
// bump backs up and spins, and the cleaning tree resumes cleaning after a goal.
#include <gtest/gtest.h>

#include <cmath>

#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::navigation {
namespace {

const std::string kNavTree = ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml";
const std::string kCleanNavTree = ROOMBA_RRT_CONFIG_DIR "/roomba_clean_nav_tree.xml";

NavLeafConfig configFor(const world::World& world) {
  planning::Problem room = world_planning::roomProblem(world);
  room.clearance = kDefaultClearance;
  return inProcessNavConfig(room, defaultNavPlannerOptions(), InProcessPlanner::Mode::kInline);
}

/// The simulator and a navigation tree in one loop.
struct Loop {
  Loop(const std::string& tree_file, const std::string& world_file = "roomba_world_furnished.yaml")
      : sim(world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/" + world_file)),
        nav(configFor(sim.world()), 1, tree_file) {}

  /// Steps until the goal is no longer active or `seconds` pass; counts bumper presses.
  void run(double seconds) {
    const long steps = std::lround(seconds * 60);
    for (long i = 0; i < steps; ++i) {
      step();
      if (nav.outcome() != GoalOutcome::kActive) return;
    }
  }
  robot::Velocity step() {
    const robot::BumperState bumper = sim.senseContact();
    bumps += bumper.pressed ? 1 : 0;
    const robot::Velocity cmd = nav.tick(bumper, sim.pose());
    EXPECT_TRUE(std::isfinite(cmd.v) && std::isfinite(cmd.w));
    sim.move(cmd);
    return cmd;
  }

  sim::Simulator sim;
  NavBt nav;
  int bumps = 0;
};

double distanceTo(const robot::Pose2D& a, const robot::Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

TEST(NavBt, a_tree_is_navigation_when_it_or_its_include_uses_a_navigation_leaf) {
  EXPECT_TRUE(usesNavigationLeaves(kNavTree));
  EXPECT_TRUE(usesNavigationLeaves(kCleanNavTree));  // through <include> and SubTree
  EXPECT_FALSE(usesNavigationLeaves(ROOMBA_RRT_CONFIG_DIR "/roomba_tree.xml"));
  EXPECT_THROW(usesNavigationLeaves("/nonexistent/tree.xml"), bt::TreeFileError);
}

TEST(NavBt, the_tree_nodes_model_describes_every_leaf_roomba_bt_knows) {
  const std::string model = treeNodesModel();
  for (const char* node :
       {"<Action ID=\"MoveForward\"", "<Action ID=\"ComputePath\"", "<Condition ID=\"HasGoal\"",
        "<Condition ID=\"IsBumped\"", "<Control ID=\"RecoveryNode\"",
        "<Decorator ID=\"RateController\"", "<output_port name=\"path\" type=\"Path\""}) {
    EXPECT_NE(model.find(node), std::string::npos) << node;
  }
}

TEST(NavBt, new_follower_limits_apply_while_driving) {
  Loop loop(kNavTree);
  loop.nav.setGoal({1.0, 1.3, M_PI});         // past the round table, above the sofa
  for (int i = 0; i < 120; ++i) loop.step();  // under way at up to 0.3 m/s
  FollowerParams slow;
  slow.max_linear_speed = 0.1;
  loop.nav.setFollowerParams(slow);
  double fastest = 0;
  for (int i = 0; i < 600 && loop.nav.outcome() == GoalOutcome::kActive; ++i) {
    fastest = std::max(fastest, std::fabs(loop.step().v));
  }
  EXPECT_LE(fastest, 0.1 + 1e-12);
  EXPECT_GT(fastest, 0.05);  // still driving
  FollowerParams bad;
  bad.max_linear_speed = -1;
  EXPECT_THROW(loop.nav.setFollowerParams(bad), util::InvalidInput);
}

TEST(NavBt, without_a_goal_the_robot_stands_still) {
  Loop loop(kNavTree);
  for (int i = 0; i < 120; ++i) {
    const robot::Velocity cmd = loop.step();
    EXPECT_EQ(cmd.v, 0.0);
    EXPECT_EQ(cmd.w, 0.0);
  }
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kNone);
  EXPECT_EQ(loop.nav.stateName(), "Idle");
}

TEST(NavBt, drives_around_furniture_to_the_goal_without_a_bump) {
  Loop loop(kNavTree);
  const robot::Pose2D goal{1.0, 1.3, M_PI};  // past the round table, above the sofa
  loop.nav.setGoal(goal);
  loop.run(90);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
  EXPECT_LE(distanceTo(loop.sim.pose(), goal), 0.05 + 1e-6);
  EXPECT_LE(std::fabs(robot::wrapAngle(loop.sim.pose().theta - goal.theta)), 0.05 + 1e-6);
  EXPECT_EQ(loop.bumps, 0);
  ASSERT_NE(loop.nav.path(), nullptr);
  // Afterwards it stands still again.
  EXPECT_EQ(loop.step().v, 0.0);
}

TEST(NavBt, reaches_the_corridor_behind_the_bench) {
  Loop loop(kNavTree);
  const robot::Pose2D goal{3.0, 4.55, 0.0};  // between the bench and the top wall
  loop.nav.setGoal(goal);
  loop.run(120);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
  EXPECT_LE(distanceTo(loop.sim.pose(), goal), 0.05 + 1e-6);
  EXPECT_EQ(loop.bumps, 0);
}

TEST(NavBt, a_goal_inside_the_sofa_is_aborted_with_the_reason_and_the_robot_stays) {
  Loop loop(kNavTree);
  const robot::Pose2D start = loop.sim.pose();
  loop.nav.setGoal({0.8, 0.3, 0.0});
  loop.run(30);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kAborted);
  EXPECT_NE(loop.nav.message().find("goal: inside rectangles[0]"), std::string::npos)
      << loop.nav.message();
  EXPECT_LT(distanceTo(loop.sim.pose(), start), 1e-9);
}

TEST(NavBt, a_new_goal_preempts_the_current_one) {
  Loop loop(kNavTree);
  loop.nav.setGoal({5.5, 2.5, 0.0});
  loop.run(2);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kActive);
  const robot::Pose2D second{2.0, 2.0, M_PI / 2};
  loop.nav.setGoal(second);
  loop.run(90);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
  EXPECT_LE(distanceTo(loop.sim.pose(), second), 0.05 + 1e-6);
}

TEST(NavBt, a_cancel_stops_the_robot_at_once) {
  Loop loop(kNavTree);
  loop.nav.setGoal({5.5, 2.5, 0.0});
  loop.run(3);
  EXPECT_GT(std::fabs(loop.sim.lastCommand().v), 0.05);
  loop.nav.cancelGoal();
  const robot::Velocity cmd = loop.step();
  EXPECT_EQ(cmd.v, 0.0);
  EXPECT_EQ(cmd.w, 0.0);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kNone);
}

TEST(NavBt, a_non_finite_goal_is_refused_naming_the_field) {
  Loop loop(kNavTree);
  try {
    loop.nav.setGoal({1.0, std::nan(""), 0.0});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "goal.y: must be finite");
  }
}

TEST(NavBt, a_bump_backs_up_spins_and_replans) {
  // A bare unicycle (no walls hit): the bumper is pressed by hand once while following.
  Loop loop(kNavTree);
  loop.nav.setGoal({5.0, 2.4, 0.0});
  for (int i = 0; i < 60; ++i) loop.step();
  EXPECT_EQ(loop.nav.stateName(), "FollowPath");
  loop.nav.tick({true, true, true}, loop.sim.pose());  // the bump
  robot::Velocity cmd = loop.nav.tick({}, loop.sim.pose());
  EXPECT_EQ(loop.nav.stateName(), "BackUp");
  EXPECT_LT(cmd.v, 0.0);
  bool spun = false;
  for (int i = 0; i < 300 && loop.nav.stateName() != "FollowPath"; ++i) {
    cmd = loop.nav.tick({}, loop.sim.pose());
    spun = spun || loop.nav.stateName() == "Spin";
  }
  EXPECT_TRUE(spun);
  EXPECT_EQ(loop.nav.stateName(), "FollowPath");  // replanned and following again
  loop.run(90);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
}

TEST(NavBt, a_robot_pushed_off_its_path_replans_from_where_it_is) {
  Loop loop(kNavTree);
  const robot::Pose2D goal{5.0, 2.4, 0.0};
  loop.nav.setGoal(goal);
  for (int i = 0; i < 120; ++i) loop.step();
  ASSERT_EQ(loop.nav.stateName(), "FollowPath");
  const Path first = *loop.nav.path();
  loop.sim.setPose({4.0, 1.2, 0.0});  // carried 1.2 m off the straight path
  loop.step();                        // FollowPath: strayed
  EXPECT_NE(loop.nav.tree().blackboard().get<std::string>("error")->find("strayed"),
            std::string::npos);
  for (int i = 0; i < 60 && loop.nav.stateName() != "FollowPath"; ++i) loop.step();
  ASSERT_EQ(loop.nav.stateName(), "FollowPath");       // replanned, no back-up (it was not bumped)
  EXPECT_NEAR(loop.nav.path()->front().x, 4.0, 0.05);  // from where it was put
  EXPECT_NEAR(loop.nav.path()->front().y, 1.2, 0.05);
  EXPECT_NE(loop.nav.path()->front().y, first.front().y);
  loop.run(60);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
  EXPECT_LE(distanceTo(loop.sim.pose(), goal), 0.05 + 1e-6);
}

TEST(NavBt, a_blocked_path_is_noticed_within_half_a_second_and_replanned) {
  Loop loop(kNavTree);
  const robot::Pose2D goal{5.0, 2.4, 0.0};
  loop.nav.setGoal(goal);
  for (int i = 0; i < 60; ++i) loop.step();
  // The path changes under the robot to one through the bin (as a moved obstacle would make it).
  const robot::Pose2D here = loop.sim.pose();
  loop.nav.tree().blackboard().set<Path>("path", {{here.x, here.y}, {4.9, 3.3}, {5.0, 2.4}});
  bool noticed = false;
  for (int i = 0; i < 31 && !noticed; ++i) {
    loop.step();
    const std::string* error = loop.nav.tree().blackboard().get<std::string>("error");
    noticed = error && *error == "the path is blocked";
  }
  EXPECT_TRUE(noticed);
  loop.run(60);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
  EXPECT_EQ(loop.bumps, 0);
}

TEST(NavBt, the_cleaning_tree_cleans_until_a_goal_and_resumes_after_it) {
  Loop loop(kCleanNavTree);
  for (int i = 0; i < 30; ++i) loop.step();
  EXPECT_EQ(loop.nav.stateName(), "MoveForward");
  const robot::Pose2D goal{3.0, 2.4, 0.0};
  loop.nav.setGoal(goal);
  loop.run(90);
  EXPECT_EQ(loop.nav.outcome(), GoalOutcome::kSucceeded) << loop.nav.message();
  EXPECT_LE(distanceTo(loop.sim.pose(), goal), 0.05 + 1e-6);
  loop.step();  // the idle tick of the finished root
  loop.step();
  EXPECT_EQ(loop.nav.stateName(), "MoveForward");
  EXPECT_GT(loop.sim.lastCommand().v, 0.0);
}

TEST(NavBt, the_tree_files_name_their_errors) {
  const world::World world;
  const std::string bad = R"(<root><BehaviorTree>
    <FollowPath path="{path}" goal="{goal}" pose="{pose}"/>
  </BehaviorTree></root>)";
  try {
    NavBt nav(configFor(world), 1, bad, "bad.xml");
    FAIL();
  } catch (const bt::TreeFileError& e) {
    EXPECT_STREQ(e.what(),
                 "bad.xml:2: <FollowPath>: port 'path' reads blackboard key 'path', which nothing "
                 "writes (no output port of the tree names it and the application did not "
                 "declare it)");
  }
  const std::string typo = R"(<root><BehaviorTree>
    <ComputePath start="{pose}" goal="{pose}" path="{goal}"/>
  </BehaviorTree></root>)";
  try {
    NavBt nav(configFor(world), 1, typo, "typo.xml");
    FAIL();
  } catch (const bt::TreeFileError& e) {
    EXPECT_STREQ(e.what(),
                 "typo.xml:2: <ComputePath>: port 'path' (Path: the plan, start to goal): "
                 "blackboard key 'goal' holds Pose2D, not Path");
  }
}

}  // namespace
}  // namespace roomba_rrt::navigation
