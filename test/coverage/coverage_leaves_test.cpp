// The cleaning leaves' contracts (coverage_leaves.h): ports, statuses, the leg bookkeeping, resume
// after a bump where the robot stopped, a row given up after N tries; and the cleaning tree
// (config/roomba_coverage_tree.xml) in navigation::NavBt with the simulator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <string>

#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::coverage {
namespace {

using navigation::NavBt;
using navigation::NavContext;
using navigation::NavLeafConfig;

const std::string kCoverageTree = ROOMBA_RRT_CONFIG_DIR "/roomba_coverage_tree.xml";

world::World smallRoom() {
  world::World world;
  world.room.width = 2.0;
  world.room.height = 1.5;
  world.robot().initial_pose = {1.0, 0.75, 0.0};
  return world;
}

NavLeafConfig cleaningConfig(const world::World& world,
                             std::shared_ptr<const CoveragePlanner> planner) {
  NavLeafConfig config = navigation::inProcessNavConfig(world_planning::roomProblem(world));
  config.more_leaves.push_back(coverageLeaves(std::move(planner)));
  return config;
}

/// A 3 m × 2 m room with a pillar in the middle, which its rows pass round.
world::World pillarRoom() {
  world::World world;
  world.room.width = 3.0;
  world.room.height = 2.0;
  world.room.circles.push_back({{1.5, 1.0}, 0.12});
  world.robot().initial_pose = {0.5, 0.5, 0.0};
  return world;
}

/// The leaves on a blackboard, driven by hand or with the simulator, one leaf per tree.
struct LeafTest : ::testing::Test {
  explicit LeafTest(world::World room = smallRoom())
      : world(std::move(room)),
        planner(std::make_shared<const CoveragePlanner>(world)),
        context(1),
        sim(world) {
    board->set<robot::Pose2D>("pose", world.robot().initial_pose);
    context.params = &params;
    navigation::registerNavLeaves(factory, cleaningConfig(world, planner), context);
  }
  bt::Tree build(const std::string& body) {
    return factory.buildFromText("<root><BehaviorTree>" + body + "</BehaviorTree></root>", "t",
                                 board);
  }
  /// One tick of `tree` with the simulator's bumper and pose; moves the robot.
  bt::Status step(bt::Tree& tree) {
    context.bumper = sim.senseContact();
    board->set<robot::Pose2D>("pose", sim.pose());
    context.cmd = {};
    const bt::Status status = tree.tick();
    context.previous_cmd = context.cmd;
    sim.move(context.cmd);
    return status;
  }
  const CoverageProgress& progress() const { return *board->get<CoverageProgress>("coverage"); }
  void plan() {
    bt::Tree tree = build(kPlan);
    ASSERT_EQ(tree.tick(), bt::Status::kSuccess);
  }
  /// Follows until the robot is in the middle of a row (leg index ≥ `min_leg`).
  void driveIntoARow(bt::Tree& follow, std::size_t min_leg) {
    for (int i = 0; i < 60 * 60; ++i) {
      ASSERT_EQ(step(follow), bt::Status::kRunning);
      const CoverageProgress& p = progress();
      const Leg& leg = p.plan.legs[p.leg];
      if (p.leg >= min_leg && leg.kind == Leg::Kind::kRow &&
          geometry::distance(leg.points.front(), {sim.pose().x, sim.pose().y}) > 0.5 &&
          geometry::distance(leg.points.back(), {sim.pose().x, sim.pose().y}) > 0.5) {
        return;
      }
    }
    FAIL() << "never in the middle of a row";
  }

  /// Follows the plan to the end (SUCCESS within 300 s) and counts the legs changed on the move
  /// (driving forwards) before the touch-up, into or out of a transit k for which joined(k) holds:
  /// a transit driven with the rows around it.
  template <class Joined>
  int changesOnTheMove(bt::Tree& follow, const std::vector<Leg>& legs, Joined joined) {
    int changes = 0;
    bt::Status status = bt::Status::kRunning;
    for (int i = 0; i < 60 * 300 && status == bt::Status::kRunning; ++i) {
      const std::size_t leg = progress().leg;
      const bool rows = !progress().touchingUp();
      status = step(follow);
      if (!rows || progress().touchingUp() || progress().leg != leg + 1 || context.cmd.v <= 0) {
        continue;
      }
      changes += joined(leg) || (legs[leg].kind == Leg::Kind::kRow && joined(leg + 1));
    }
    EXPECT_EQ(status, bt::Status::kSuccess);
    return changes;
  }

  /// Follows `given` (set as the blackboard's progress) until FollowCoverage ends or `seconds`
  /// pass, calling watch() after every tick; the last status.
  template <class Watch>
  bt::Status followGiven(const CoverageProgress& given, int seconds, Watch watch) {
    board->set<CoverageProgress>("coverage", given);
    bt::Tree follow = build(kFollow);
    bt::Status status = bt::Status::kRunning;
    for (int i = 0; i < 60 * seconds && status == bt::Status::kRunning; ++i) {
      status = step(follow);
      watch();
    }
    return status;
  }

  static constexpr const char* kPlan =
      R"(<PlanCoverage start="{pose}" coverage="{coverage}" error="{error}"/>)";
  static constexpr const char* kFollow =
      R"(<FollowCoverage coverage="{coverage}" pose="{pose}" error="{error}"/>)";
  static constexpr const char* kTouchUp =
      R"(<PlanTouchUp coverage="{coverage}" pose="{pose}" error="{error}"/>)";

  world::World world;
  std::shared_ptr<const CoveragePlanner> planner;
  behavior::RoombaParams params;
  bt::TreeFactory factory;
  NavContext context;
  std::shared_ptr<bt::Blackboard> board = std::make_shared<bt::Blackboard>();
  sim::Simulator sim;
};

TEST(CoverageLeaves, the_nodes_model_lists_the_leaves_with_their_ports) {
  const std::string model = navigation::treeNodesModel({coverageLeaves(nullptr)});
  for (const char* text : {"<Action ID=\"PlanCoverage\"", "<Action ID=\"FollowCoverage\"",
                           "<Action ID=\"PlanTouchUp\"", "<Action ID=\"ResumeCoverage\"",
                           "<Condition ID=\"CoverageDone\"", "name=\"transit_speed\"",
                           "name=\"skip_after\"", "type=\"CoverageProgress\""}) {
    EXPECT_NE(model.find(text), std::string::npos) << text << " not in\n" << model;
  }
  // The plan's progress is read and written by the leaves that drive and resume it.
  const auto ports_of = [&](const std::string& id) {
    const auto begin = model.find("ID=\"" + id + "\"");
    return begin == std::string::npos ? ""
                                      : model.substr(begin, model.find("</Action>", begin) - begin);
  };
  EXPECT_NE(ports_of("FollowCoverage").find("<inout_port name=\"coverage\""), std::string::npos)
      << model;
  EXPECT_NE(ports_of("ResumeCoverage").find("<inout_port name=\"coverage\""), std::string::npos);
  EXPECT_NE(ports_of("PlanCoverage").find("<output_port name=\"coverage\""), std::string::npos);
  // Without the registrar the navigation model stays as it was.
  EXPECT_EQ(navigation::treeNodesModel().find("PlanCoverage"), std::string::npos);
}

TEST(CoverageLeaves, described_only_they_cannot_be_built) {
  NavContext context(1);
  bt::TreeFactory factory;
  NavLeafConfig config;
  config.planners = [] { return std::unique_ptr<navigation::PathPlanner>(); };
  config.more_leaves.push_back(coverageLeaves(nullptr));
  navigation::registerNavLeaves(factory, config, context);
  EXPECT_ANY_THROW(factory.buildFromText(
      R"(<root><BehaviorTree><PlanCoverage start="{pose}" coverage="{c}"/></BehaviorTree></root>)",
      "t"));
}

TEST(CoverageLeaves, the_cleaning_tree_is_a_navigation_tree_roomba_bt_runs) {
  EXPECT_FALSE(navigation::usesNavigationLeaves(ROOMBA_RRT_CONFIG_DIR "/roomba_tree.xml",
                                                {coverageLeaves(nullptr)}));
  EXPECT_TRUE(navigation::usesNavigationLeaves(kCoverageTree, {coverageLeaves(nullptr)}));
}

TEST_F(LeafTest, plan_coverage_without_a_pose_fails_with_the_reason) {
  board = std::make_shared<bt::Blackboard>();
  board->declare<robot::Pose2D>("pose");  // declared, never written
  bt::Tree tree = build(kPlan);
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"), "no start pose to plan from");
}

TEST_F(LeafTest, plan_coverage_writes_the_plan_from_the_pose) {
  plan();
  const CoverageProgress& p = progress();
  ASSERT_FALSE(p.plan.legs.empty());
  EXPECT_EQ(p.leg, 0u);
  EXPECT_EQ(p.tries, 0);
  EXPECT_FALSE(p.done());
  EXPECT_EQ(p.plan.legs.front().points.front().x, world.robot().initial_pose.x);
  EXPECT_EQ(p.plan.legs.front().points.front().y, world.robot().initial_pose.y);
  // What is left to drive, for ~coverage_path: every leg's points, joined.
  const Polyline rest = remainingPath(p);
  EXPECT_EQ(rest.front().x, world.robot().initial_pose.x);
  EXPECT_EQ(rest.back().x, p.plan.legs.back().points.back().x);
}

TEST_F(LeafTest, plan_coverage_inside_furniture_fails_and_leaves_nothing_to_do) {
  world.room.circles.push_back({{1.0, 0.75}, 0.3});
  LeafTest::planner = std::make_shared<const CoveragePlanner>(world);
  bt::TreeFactory other;
  navigation::registerNavLeaves(other, cleaningConfig(world, planner), context);
  bt::Tree tree = other.buildFromText(
      std::string("<root><BehaviorTree>") + kPlan + "</BehaviorTree></root>", "t", board);
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"),
            "nothing to clean: no floor can be reached from the start");
  EXPECT_TRUE(progress().done());  // CoverageDone: the tree stops instead of planning again
}

TEST_F(LeafTest, follow_coverage_without_a_plan_fails_with_the_reason) {
  bt::Tree tree = build(kFollow);
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"), "no coverage plan to follow");
}

TEST_F(LeafTest, follow_coverage_drives_rows_at_the_forward_speed_and_transits_faster) {
  plan();
  bt::Tree follow = build(
      R"(<FollowCoverage coverage="{coverage}" pose="{pose}" transit_speed="0.7" error="{error}"/>)");
  double fastest_row = 0, fastest_transit = 0;
  bt::Status status = bt::Status::kRunning;
  for (int i = 0; i < 60 * 300 && status == bt::Status::kRunning; ++i) {
    const CoverageProgress& p = progress();
    const bool row = !p.done() && p.plan.legs[p.leg].kind == Leg::Kind::kRow;
    status = step(follow);
    double& fastest = row ? fastest_row : fastest_transit;
    fastest = std::max(fastest, context.cmd.v);
    if (status == bt::Status::kRunning) {
      EXPECT_EQ(context.state_name, &follow.root().name());
    }
  }
  EXPECT_EQ(status, bt::Status::kSuccess);  // the plan in hand is driven; the touch-up is not
  EXPECT_EQ(progress().leg, progress().plan.legs.size());
  EXPECT_FALSE(progress().touchingUp());
  EXPECT_NEAR(fastest_row, params.forward_speed, 1e-9);
  EXPECT_GT(fastest_transit, params.forward_speed);
  EXPECT_LE(fastest_transit, 0.7 + 1e-9);
  EXPECT_GT(sim.coverage(), 0.9);
  EXPECT_EQ(progress().bumps, 0);
}

TEST_F(LeafTest, the_u_turn_between_two_rows_is_driven_without_stopping) {
  plan();
  bt::Tree follow = build(kFollow);
  const std::vector<Leg> legs = progress().plan.legs;
  auto step_at = [&](std::size_t k) {  // a short transit into a row: a U-turn's step
    return k + 1 < legs.size() && legs[k].kind == Leg::Kind::kTransit &&
           legs[k + 1].kind == Leg::Kind::kRow && geometry::pathLength(legs[k].points) < 0.5;
  };
  // Each step is entered from its row and left into the next one on the move.
  int changes_expected = 0;
  for (std::size_t k = 0; k < legs.size(); ++k) {
    changes_expected += step_at(k) + (legs[k].kind == Leg::Kind::kRow && step_at(k + 1));
  }
  ASSERT_GT(changes_expected, 4);
  EXPECT_EQ(changesOnTheMove(follow, legs, step_at), changes_expected);
}

TEST_F(LeafTest, rows_that_go_on_from_one_another_are_driven_without_stopping) {
  // The loop along the walls (wall_loop.h) is a chain of rows, each starting where the one before
  // it ended, round the room: the robot drives on through the corners where they meet.
  const Polyline corners{{0.4, 0.4}, {1.0, 0.4}, {1.6, 0.4}, {1.6, 1.1},
                         {1.0, 1.1}, {0.4, 1.1}, {0.4, 0.4}};
  CoverageProgress loop;
  loop.swept.assign(planner->freeSpace().size(), 1);  // nothing left for the touch-up
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    loop.plan.legs.push_back({Leg::Kind::kRow, {corners[k], corners[k + 1]}});
  }
  sim.setPose({0.4, 0.4, 0.0});
  board->set<robot::Pose2D>("pose", sim.pose());
  // From the first row's middle to the last one's: never slower than the arcs round the corners
  // (0.28 m/s); stopping at each row's end and turning there, it would stand still five times.
  double slowest = 1;
  EXPECT_EQ(followGiven(loop, 60,
                        [&] {
                          const std::size_t leg = progress().leg;
                          const bool between =
                              (leg > 0 || sim.pose().x > 0.7) && leg + 1 < loop.plan.legs.size();
                          if (between && !progress().touchingUp()) {
                            slowest = std::min(slowest, context.cmd.v);
                          }
                        }),
            bt::Status::kSuccess);
  EXPECT_GT(slowest, 0.2);
  EXPECT_EQ(progress().bumps, 0);
}

struct PillarTest : LeafTest {
  PillarTest() : LeafTest(pillarRoom()) {}
};

TEST_F(PillarTest, the_way_round_a_pillar_between_two_pieces_of_a_row_is_driven_without_stopping) {
  plan();
  bt::Tree follow = build(kFollow);
  const std::vector<Leg> legs = progress().plan.legs;
  auto round_at = [&](std::size_t k) {  // a transit between two pieces of one row
    return k > 0 && k + 1 < legs.size() && legs[k].kind == Leg::Kind::kTransit &&
           legs[k - 1].kind == Leg::Kind::kRow && legs[k + 1].kind == Leg::Kind::kRow &&
           legs[k - 1].points.back().y == legs[k + 1].points.front().y;
  };
  int rounds = 0;
  for (std::size_t k = 0; k < legs.size(); ++k) rounds += round_at(k);
  ASSERT_GE(rounds, 2);
  // Each is entered from its row and left into the row's next piece on the move.
  EXPECT_EQ(changesOnTheMove(follow, legs, round_at), 2 * rounds);
  EXPECT_EQ(progress().bumps, 0);
  EXPECT_GT(sim.coverage(), 0.9);
}

TEST_F(LeafTest, a_touch_up_stop_the_way_turns_back_at_is_reached_not_cut) {
  // A touch-up stop is a row of no length. The way there and the way on reverse at it: driven
  // as one path, the carrot would jump behind the robot before it got there.
  CoverageProgress touch_up;
  touch_up.touch_ups = 1;  // the first pass; the floor is swept but for the stop
  touch_up.swept.assign(planner->freeSpace().size(), 1);
  const Point2 start{1.0, 0.75}, stop{1.3, 0.75};
  touch_up.plan.legs = {{Leg::Kind::kTransit, {start, stop}},
                        {Leg::Kind::kRow, {stop, stop}},
                        {Leg::Kind::kTransit, {stop, start}},
                        {Leg::Kind::kRow, {start, start}}};
  double furthest = 0;
  EXPECT_EQ(followGiven(touch_up, 20, [&] { furthest = std::max(furthest, sim.pose().x); }),
            bt::Status::kSuccess);
  EXPECT_GT(furthest, stop.x - 0.015);  // within the follower's 1 cm of the stop
}

/// The small room 7 mm narrower: its right wall is off the lattice's cell boundaries, and the last
/// lattice column stands 5.5 mm from it (floor the rows' 1 cm clearance keeps them from).
world::World offLatticeRoom() {
  world::World world = smallRoom();
  world.room.width -= 0.007;
  return world;
}

struct EdgeTest : LeafTest {
  EdgeTest() : LeafTest(offLatticeRoom()) {}
};

TEST_F(EdgeTest, a_row_along_the_wall_is_driven_closer_than_the_rows_guard_allows_without_a_bump) {
  // All swept but the band by the right wall: the touch-up's row along it (edge cleaning) keeps
  // 3 mm; the rows' guard keeps 5 mm and would hold the robot off it.
  const auto& space = planner->freeSpace();
  CoverageProgress touch_up;
  touch_up.touch_ups = 1;
  touch_up.swept.assign(space.size(), 1);
  int band = 0;
  for (int k = 0; k < space.size(); ++k) {
    const Point2 p = space.point(k);
    if (p.x > world.room.width - 0.01 && p.y > 0.3 && p.y < 1.2) touch_up.swept[k] = 0, ++band;
  }
  ASSERT_GT(band, 30);
  touch_up.plan = planner->touchUp(touch_up.swept, {1.0, 0.75});
  ASSERT_TRUE(std::any_of(touch_up.plan.legs.begin(), touch_up.plan.legs.end(),
                          [](const Leg& leg) { return leg.along_wall; }));
  board->set<CoverageProgress>("coverage", touch_up);
  bt::Tree follow = build(kFollow);
  double closest = world.room.width;  // the disc's least gap to the right wall
  bool contact = false;
  bt::Status status = bt::Status::kRunning;
  for (int i = 0; i < 60 * 30 && status == bt::Status::kRunning; ++i) {
    status = step(follow);
    closest = std::min(closest, world.room.width - sim.pose().x - world.robot().radius);
    contact = contact || sim.senseContact().pressed;
  }
  EXPECT_EQ(status, bt::Status::kSuccess);
  EXPECT_FALSE(contact);
  EXPECT_LT(closest, planner->options().clearance / 2);
  EXPECT_GT(closest, 0.0);
  int left = 0;
  for (int k = 0; k < space.size(); ++k) left += !progress().swept[k];
  EXPECT_LE(left, 6);  // the ramps' ends
}

TEST_F(EdgeTest, plan_touch_up_leaves_the_rows_along_the_wall_to_the_pass_edge_cleaning_is_from) {
  // The touch-up tree on a built map (config/roomba_touch_up_tree.xml): the first pass goes for
  // the spots, the second cleans along the walls too.
  const auto& space = planner->freeSpace();
  CoverageProgress touch_up;
  touch_up.swept.assign(space.size(), 1);
  for (int k = 0; k < space.size(); ++k) {
    const Point2 p = space.point(k);
    if (p.x > world.room.width - 0.01 && p.y > 0.3 && p.y < 1.2) touch_up.swept[k] = 0;
  }
  board->set<CoverageProgress>("coverage", touch_up);
  board->set<robot::Pose2D>("pose", {1.0, 0.75, 0.0});
  bt::Tree tree = build(
      R"(<PlanTouchUp coverage="{coverage}" pose="{pose}" edge_cleaning_from="2" error="{error}"/>)");
  auto along_wall = [&] {
    const auto& legs = progress().plan.legs;
    return std::count_if(legs.begin(), legs.end(), [](const Leg& leg) { return leg.along_wall; });
  };
  ASSERT_EQ(tree.tick(), bt::Status::kSuccess);
  EXPECT_EQ(progress().touch_ups, 1);
  EXPECT_EQ(along_wall(), 0);
  CoverageProgress driven = progress();  // the first pass driven, the band still missed
  driven.leg = driven.plan.legs.size();
  board->set<CoverageProgress>("coverage", driven);
  ASSERT_EQ(tree.tick(), bt::Status::kSuccess);
  EXPECT_EQ(progress().touch_ups, 2);
  EXPECT_EQ(along_wall(), 1);
}

TEST_F(LeafTest, plan_touch_up_goes_for_spots_down_to_min_spot_area_in_its_first_pass) {
  // The touch-up round on a built map (config/roomba_touch_up_tree.xml) goes for every spot of
  // 40 cm² or more in its first pass; without min_spot_area the first pass leaves a spot of
  // 80 cm² (under 120) to the second.
  const auto& space = planner->freeSpace();
  CoverageProgress missed;
  missed.swept.assign(space.size(), 1);
  int spot = 0;
  for (int k = 0; k < space.size(); ++k) {
    const Point2 p = space.point(k);
    if (std::abs(p.x - 1.0) < 0.045 && std::abs(p.y - 0.75) < 0.045) missed.swept[k] = 0, ++spot;
  }
  ASSERT_GT(spot, 0);
  board->set<robot::Pose2D>("pose", {0.5, 0.5, 0.0});
  auto visits = [&](const std::string& attributes) {
    board->set<CoverageProgress>("coverage", missed);
    bt::Tree tree = build(R"(<PlanTouchUp coverage="{coverage}" pose="{pose}" )" + attributes +
                          R"( error="{error}"/>)");
    EXPECT_EQ(tree.tick(), bt::Status::kSuccess);
    EXPECT_EQ(progress().touch_ups, 1);
    const auto& legs = progress().plan.legs;
    return std::count_if(legs.begin(), legs.end(),
                         [](const Leg& leg) { return leg.kind == Leg::Kind::kRow; });
  };
  EXPECT_EQ(visits(""), 0);
  EXPECT_EQ(visits(R"(min_spot_area="0.004")"), 1);
}

TEST_F(LeafTest, follow_coverage_fails_on_a_bump_and_keeps_the_leg_it_was_in) {
  plan();
  bt::Tree follow = build(kFollow);
  driveIntoARow(follow, 1);
  const std::size_t leg = progress().leg;
  context.bumper.pressed = true;
  EXPECT_EQ(follow.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"), "bumped");
  EXPECT_EQ(progress().leg, leg);
  EXPECT_EQ(progress().bumps, 1);
}

TEST_F(LeafTest, follow_coverage_fails_when_the_robot_makes_no_progress_for_10_s) {
  plan();
  bt::Tree follow = build(kFollow);
  driveIntoARow(follow, 1);
  const std::size_t leg = progress().leg;
  // The wheels spin: the pose stays where it is, whatever the command.
  const int ticks_in_10_s = static_cast<int>(10.0 * 60);
  bt::Status status = bt::Status::kRunning;
  int ticks = 0;
  for (; ticks < 2 * ticks_in_10_s && status == bt::Status::kRunning; ++ticks) {
    context.cmd = {};
    status = follow.tick();
  }
  EXPECT_EQ(status, bt::Status::kFailure);
  EXPECT_GT(ticks, ticks_in_10_s - 60);  // not before about 10 s (progress in the first ticks)
  EXPECT_LE(ticks, ticks_in_10_s + 2);
  EXPECT_EQ(*board->get<std::string>("error"), "no progress along the leg for 10 s");
  EXPECT_EQ(progress().leg, leg);  // for ResumeCoverage
  EXPECT_EQ(progress().bumps, 0);
}

TEST_F(LeafTest, resume_after_a_bump_continues_the_row_where_it_stopped) {
  plan();
  bt::Tree follow = build(kFollow);
  driveIntoARow(follow, 1);
  const CoverageProgress before = progress();
  const Leg row = before.plan.legs[before.leg];
  const Point2 at{sim.pose().x, sim.pose().y};
  bt::Tree resume = build(R"(<ResumeCoverage coverage="{coverage}" pose="{pose}"/>)");
  EXPECT_EQ(resume.tick(), bt::Status::kSuccess);
  const CoverageProgress& after = progress();
  EXPECT_EQ(after.leg, 0u);
  EXPECT_EQ(after.tries, 1);
  EXPECT_EQ(after.skipped_rows, 0);
  // The rest of the same row, from next to the robot (not from the row's start, nor the plan's).
  const Leg& first_row = after.plan.legs[after.plan.legs.front().kind == Leg::Kind::kRow ? 0 : 1];
  EXPECT_EQ(first_row.kind, Leg::Kind::kRow);
  EXPECT_LT(geometry::distance(first_row.points.front(), at), 0.05);
  EXPECT_EQ(first_row.points.back().x, row.points.back().x);
  EXPECT_EQ(first_row.points.back().y, row.points.back().y);
  // Every later leg as it was.
  EXPECT_EQ(after.plan.legs.back().points.back().x, before.plan.legs.back().points.back().x);
  EXPECT_EQ(after.plan.legs.back().points.back().y, before.plan.legs.back().points.back().y);
  // Following goes on with that rest.
  EXPECT_EQ(step(follow), bt::Status::kRunning);
}

TEST_F(LeafTest, a_row_is_given_up_after_skip_after_resumes_without_finishing_it) {
  plan();
  bt::Tree follow = build(kFollow);
  driveIntoARow(follow, 1);
  const CoverageProgress before = progress();
  const Point2 row_end = before.plan.legs[before.leg].points.back();
  bt::Tree resume =
      build(R"(<ResumeCoverage coverage="{coverage}" pose="{pose}" skip_after="2"/>)");
  ASSERT_EQ(resume.tick(), bt::Status::kSuccess);  // first try: the rest of the row
  EXPECT_EQ(progress().skipped_rows, 0);
  ASSERT_EQ(resume.tick(), bt::Status::kSuccess);  // second: given up
  const CoverageProgress& after = progress();
  EXPECT_EQ(after.skipped_rows, 1);
  EXPECT_EQ(after.tries, 0);
  for (const Leg& leg : after.plan.legs) {
    if (leg.kind != Leg::Kind::kRow) continue;
    EXPECT_FALSE(leg.points.back().x == row_end.x && leg.points.back().y == row_end.y)
        << "the row given up is still in the plan";
  }
  EXPECT_LT(after.plan.legs.size(), before.plan.legs.size() - before.leg);
}

TEST_F(LeafTest, finishing_a_row_clears_the_tries) {
  plan();
  bt::Tree follow = build(kFollow);
  driveIntoARow(follow, 1);
  bt::Tree resume = build(R"(<ResumeCoverage coverage="{coverage}" pose="{pose}"/>)");
  ASSERT_EQ(resume.tick(), bt::Status::kSuccess);
  ASSERT_EQ(progress().tries, 1);
  for (int i = 0; i < 60 * 30 && progress().tries != 0; ++i) {
    ASSERT_EQ(step(follow), bt::Status::kRunning);
  }
  EXPECT_EQ(progress().tries, 0);
}

TEST_F(LeafTest, coverage_done_only_when_every_leg_is_driven) {
  board->declare<CoverageProgress>("coverage");
  bt::Tree done = build(R"(<CoverageDone coverage="{coverage}"/>)");
  EXPECT_EQ(done.tick(), bt::Status::kFailure);  // no plan yet
  plan();
  EXPECT_EQ(done.tick(), bt::Status::kFailure);
  CoverageProgress finished = progress();
  finished.leg = finished.plan.legs.size();
  board->set<CoverageProgress>("coverage", finished);
  EXPECT_EQ(done.tick(), bt::Status::kFailure);  // the rows are driven, the touch-up is not
  finished.touch_ups = CoverageProgress::kTouchUpPasses;
  board->set<CoverageProgress>("coverage", finished);
  EXPECT_EQ(done.tick(), bt::Status::kSuccess);
}

TEST_F(LeafTest, plan_touch_up_without_a_pose_or_plan_fails_with_the_reason) {
  bt::Tree touch_up = build(kTouchUp);
  EXPECT_EQ(touch_up.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"), "no coverage plan to touch up");
}

TEST_F(LeafTest, plan_touch_up_plans_each_pass_once_the_plan_in_hand_is_driven) {
  plan();
  bt::Tree touch_up = build(kTouchUp);
  const std::size_t rows = progress().plan.legs.size();
  EXPECT_EQ(touch_up.tick(), bt::Status::kSuccess);  // the rows are not driven: nothing planned
  EXPECT_EQ(progress().touch_ups, 0);
  EXPECT_EQ(progress().plan.legs.size(), rows);

  bt::Tree follow = build(kFollow);
  bt::Status status = bt::Status::kRunning;
  for (int i = 0; i < 60 * 300 && status == bt::Status::kRunning; ++i) status = step(follow);
  ASSERT_EQ(status, bt::Status::kSuccess);
  EXPECT_EQ(touch_up.tick(), bt::Status::kSuccess);  // the large spots the rows missed
  EXPECT_EQ(progress().touch_ups, 1);
  EXPECT_EQ(progress().leg, 0u);
  EXPECT_FALSE(progress().plan.legs.empty());
  EXPECT_FALSE(progress().done());
  const std::size_t first_pass = progress().plan.legs.size();
  EXPECT_EQ(touch_up.tick(), bt::Status::kSuccess);  // not driven yet: planned once only
  EXPECT_EQ(progress().touch_ups, 1);
  EXPECT_EQ(progress().plan.legs.size(), first_pass);

  // Both passes driven: a third PlanTouchUp plans nothing, and the cleaning is done.
  for (int pass = 1; pass <= CoverageProgress::kTouchUpPasses; ++pass) {
    status = bt::Status::kRunning;
    for (int i = 0; i < 60 * 300 && status == bt::Status::kRunning; ++i) status = step(follow);
    ASSERT_EQ(status, bt::Status::kSuccess);
    EXPECT_EQ(touch_up.tick(), bt::Status::kSuccess);
  }
  EXPECT_EQ(progress().touch_ups, CoverageProgress::kTouchUpPasses);
  EXPECT_TRUE(progress().done());
  EXPECT_GT(sim.coverage(), 0.97);
}

/// The cleaning tree as roomba_bt and roomba_coverage run it.
struct CleaningLoop {
  explicit CleaningLoop(const std::string& world_file)
      : CleaningLoop(world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/" + world_file)) {}
  explicit CleaningLoop(const world::World& cleaned)
      : world(cleaned),
        planner(std::make_shared<const CoveragePlanner>(world)),
        sim(world),
        nav(cleaningConfig(world, planner), 1, kCoverageTree) {}
  /// A chair in the simulated room that the planner does not know, in the middle of the lab
  /// room's first rows.
  void addUnknownChair() {
    world::World with_chair = world;
    with_chair.room.circles.push_back({{1.5, 3.0}, 0.2});
    sim = sim::Simulator(with_chair);
  }
  void run(double seconds) {
    for (long i = 0; i < std::lround(seconds * 60); ++i) {
      const robot::BumperState bumper = sim.senseContact();
      bumps += bumper.pressed && !pressed;
      pressed = bumper.pressed;
      const robot::Velocity cmd = nav.tick(bumper, sim.pose());
      moving = cmd.v != 0 || cmd.w != 0;
      if (nav.idle()) {
        const CoverageProgress* progress = findProgress(nav.tree().blackboard());
        idle_before_done += progress == nullptr || !progress->done();
      }
      sim.move(cmd);
    }
  }
  /// The part of the floor the robot can reach from its start that it has swept.
  double reachableCoverage() const {
    const sim::CoverageGrid& grid = sim.coverageGrid();
    const double reachable =
        planner->plan({world.robot().initial_pose.x, world.robot().initial_pose.y}).reachable_area;
    return grid.sweptFreeCells() * grid.cellSize() * grid.cellSize() / reachable;
  }
  world::World world;
  std::shared_ptr<const CoveragePlanner> planner;
  sim::Simulator sim;
  NavBt nav;
  int bumps = 0;
  int idle_before_done = 0;  ///< ticks NavBt::idle() (roomba_bt's ~state "Idle") said done early
  bool pressed = false, moving = false;
};

TEST(CoverageTree, cleans_the_furnished_room_without_bumping_then_stands_still) {
  CleaningLoop loop("roomba_world_furnished.yaml");
  loop.run(600);
  const CoverageProgress* progress = findProgress(loop.nav.tree().blackboard());
  ASSERT_NE(progress, nullptr);
  EXPECT_TRUE(progress->done());
  EXPECT_FALSE(loop.moving);
  EXPECT_EQ(loop.bumps, 0);
  EXPECT_GT(loop.sim.coverage(), 0.95);
}

TEST(CoverageTree, after_a_bump_backs_up_and_resumes_instead_of_starting_over) {
  // A chair the planner does not know about, in the middle of the first rows. Each row that
  // meets it is resumed from behind the chair until it is given up (skip_after="3"): the floor
  // beyond the chair on those rows stays dirty, but the rest of the plan goes on.
  CleaningLoop loop("roomba_world.yaml");
  loop.addUnknownChair();
  loop.run(600);
  const CoverageProgress* progress = findProgress(loop.nav.tree().blackboard());
  ASSERT_NE(progress, nullptr);
  EXPECT_TRUE(progress->done());
  EXPECT_GE(progress->bumps, 1);
  EXPECT_GE(progress->skipped_rows, 1);
  EXPECT_LE(progress->bumps, 3 * (progress->skipped_rows + 1));
  EXPECT_EQ(loop.bumps, progress->bumps);  // every bump seen by FollowCoverage, none elsewhere
  EXPECT_GT(loop.sim.coverage(), 0.8);
  // What was given up is reported (roomba_bt's ~coverage_report): each row's ends (rows run
  // along x), one of them through the chair, and the coverage the robot knows it reached, near
  // the simulator's.
  ASSERT_EQ(progress->skipped.size(), static_cast<std::size_t>(progress->skipped_rows));
  bool through_chair = false;
  for (const auto& [from, to] : progress->skipped) {
    EXPECT_NEAR(to.y, from.y, 1e-9);
    through_chair = through_chair || (std::abs(from.y - 3.0) < 0.2 + loop.world.robot().radius &&
                                      std::min(from.x, to.x) < 1.5 && std::max(from.x, to.x) > 1.5);
  }
  EXPECT_TRUE(through_chair);
  EXPECT_NEAR(progress->swept_fraction, loop.sim.coverage(), 0.05);
}

/// The cleaning tree seeing pose and bumper `lag` steps late, as roomba_bt does when its ticks
/// fall behind the simulator, with the pose driven forward one tick (roomba_bt's ~pose_latency).
/// With `timed`, the tree is told the times (NavBt::observeTiming), as roomba_bt tells it.
struct LateLoop {
  LateLoop(int lag, bool timed)
      : world(world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml")),
        sim(world),
        nav(lateConfig(world), 1, kCoverageTree),
        lag(lag),
        timed(timed) {}
  static NavLeafConfig lateConfig(const world::World& world) {
    NavLeafConfig config = cleaningConfig(world, std::make_shared<const CoveragePlanner>(world));
    config.pose_latency = 1.0 / 60;
    return config;
  }
  /// Runs until the cleaning is done or `seconds` have passed.
  void run(double seconds) {
    std::deque<std::pair<robot::BumperState, robot::Pose2D>> seen;
    for (long k = 0; k < std::lround(seconds * 60); ++k) {
      const robot::BumperState bumper = sim.senseContact();
      bumps += bumper.pressed && !pressed;
      pressed = bumper.pressed;
      seen.emplace_back(bumper, sim.pose());
      if (seen.size() > static_cast<std::size_t>(lag) + 1) seen.pop_front();
      if (timed) nav.observeTiming(k / 60.0, (k + 1 - static_cast<long>(seen.size())) / 60.0);
      sim.move(nav.tick(seen.front().first, seen.front().second));
      slowest = std::min(slowest, nav.speedScale());
      const CoverageProgress* progress = findProgress(nav.tree().blackboard());
      if (progress && progress->done()) return;
    }
  }
  world::World world;
  sim::Simulator sim;
  NavBt nav;
  int lag;
  bool timed;
  int bumps = 0;
  bool pressed = false;
  double slowest = 1;
};

TEST(CoverageTree, with_commands_12_steps_late_it_slows_down_and_cleans_instead_of_giving_up) {
  // At 12 steps (0.2 s) the robot overshot the rows' ends into the furniture at full speed: 19
  // bumps, rows given up three tries at a time, and from a pose pressed against a chair nothing
  // could be resumed: "done" at a third of the floor. Told the times, it drives slower.
  LateLoop late(12, true);
  late.run(1500);
  const CoverageProgress* progress = findProgress(late.nav.tree().blackboard());
  ASSERT_NE(progress, nullptr);
  EXPECT_TRUE(progress->done());
  EXPECT_LT(late.slowest, 0.5);
  EXPECT_GT(late.sim.coverage(), 0.95);

  LateLoop untold(12, false);  // the same delay, the tree not told: as before
  untold.run(1500);
  EXPECT_EQ(untold.slowest, 1);
  EXPECT_LT(untold.sim.coverage(), late.sim.coverage() - 0.1);
}

TEST(CoverageTree, on_time_it_drives_at_full_speed) {
  for (int lag : {0, 1, 3}) {
    LateLoop loop(lag, true);
    loop.run(20);
    EXPECT_EQ(loop.slowest, 1) << "lag " << lag;
  }
}

TEST(CoverageTree, state_reads_idle_only_once_the_floor_is_done_not_after_each_back_up) {
  // A client watching ~state stops the robot at "Idle". Each back-up ends with a tick that
  // returns RUNNING and commands nothing (the resume is planned, the row starts at the next
  // tick): that tick must not read as idle.
  CleaningLoop loop("roomba_world.yaml");
  loop.addUnknownChair();
  loop.run(600);
  const CoverageProgress* progress = findProgress(loop.nav.tree().blackboard());
  ASSERT_NE(progress, nullptr);
  ASSERT_GE(progress->bumps, 1);  // backed up at least once
  EXPECT_TRUE(progress->done());
  EXPECT_EQ(loop.idle_before_done, 0);
  EXPECT_TRUE(loop.nav.idle());
}

TEST(CoverageTree, placed_against_a_wall_it_cleans_instead_of_backing_up_along_it) {
  // Touching the bottom wall from the start (a robot put down by hand, or on its dock): the
  // bumper is pressed, and backing up does not release a contact at its side. It is not a bump
  // of the cleaning's: the robot drives off along its plan (the guard keeps it off the wall)
  // instead of backing up along the wall, 5 cm at a time, into the corner.
  CleaningLoop loop("roomba_world.yaml");
  world::World against_wall = loop.world;
  against_wall.robot().initial_pose = {3.2, against_wall.robot().radius, 0.0};
  loop.sim = sim::Simulator(against_wall);
  ASSERT_TRUE(loop.sim.senseContact().pressed);
  loop.run(600);
  const CoverageProgress* progress = findProgress(loop.nav.tree().blackboard());
  ASSERT_NE(progress, nullptr);
  EXPECT_TRUE(progress->done());
  EXPECT_EQ(progress->bumps, 0);
  EXPECT_GT(loop.sim.coverage(), 0.95);
}

/// An empty map of 6 m × 5 m in 5 cm cells, walls all round, as map_server would publish it.
world::World emptyMap() {
  auto grid = std::make_shared<geometry::OccupancyGrid>();
  grid->width = 120;
  grid->height = 100;
  grid->resolution = 0.05;
  grid->origin = {0.0, 0.0};
  grid->cells.assign(120 * 100, geometry::OccupancyGrid::kFree);
  for (int j = 0; j < grid->height; ++j) {
    for (int i = 0; i < grid->width; ++i) {
      if (i == 0 || j == 0 || i + 1 == grid->width || j + 1 == grid->height) {
        grid->cells[static_cast<std::size_t>(j) * grid->width + i] =
            geometry::OccupancyGrid::kOccupied;
      }
    }
  }
  return world::mapWorld(grid, world::RobotSpec{}.radius);
}

TEST(CoverageTree, a_map_cut_anywhere_is_cleaned_to_99_percent) {
  // A region whose far edges pass 2.5 mm beyond one of its lattice points: cut there, the floor
  // within the rows' clearance (1 cm) and the edge cleaning's (3 mm) of those walls stayed dirty,
  // 98.3 % of the reachable floor for good. The region is kept in whole cells, so its walls lie
  // between lattice points.
  world::World region = world::cropped(emptyMap(), {0.41, 0.38, 3.9245, 3.1445}, "--crop");
  region.robot().initial_pose = {2.0, 2.0, 0.0};
  CleaningLoop loop(region);
  loop.run(300);  // the ideal time is 55 s
  const CoverageProgress* progress = findProgress(loop.nav.tree().blackboard());
  ASSERT_NE(progress, nullptr);
  EXPECT_TRUE(progress->done());
  EXPECT_EQ(loop.bumps, 0);
  EXPECT_GE(loop.reachableCoverage(), 0.99);
}

}  // namespace
}  // namespace roomba_rrt::coverage
