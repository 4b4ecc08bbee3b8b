// The navigation leaves' contracts (nav_leaves.h) on a scripted planner, and the in-process
// planner on its worker thread.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>

#include "roomba_rrt/navigation/nav_leaves.h"

namespace roomba_rrt::navigation {
namespace {

/// A planner whose result the test releases by hand.
struct FakePlanner final : PathPlanner {
  void request(const planning::Point2& start, const planning::Point2& goal) override {
    ++requests;
    from = start;
    to = goal;
    pending = true;
  }
  bool poll(PlanReply& out) override {
    if (!pending || !ready) return false;
    out = reply;
    pending = false;
    return true;
  }
  void cancel() override {
    ++cancels;
    pending = false;
  }
  int requests = 0, cancels = 0;
  bool pending = false, ready = false;
  planning::Point2 from, to;
  PlanReply reply;
};

struct LeafTest : ::testing::Test {
  LeafTest() : context(1) {
    board->declare<robot::Pose2D>("goal");
    board->set<robot::Pose2D>("pose", {1, 2, 0});
    NavLeafConfig config;
    config.planners = [this] {
      auto p = std::make_unique<FakePlanner>();
      planner = p.get();
      return p;
    };
    registerNavLeaves(factory, config, context);
  }
  bt::Tree build(const std::string& body) {
    return factory.buildFromText("<root><BehaviorTree>" + body + "</BehaviorTree></root>", "t",
                                 board);
  }
  bt::TreeFactory factory;
  NavContext context;
  std::shared_ptr<bt::Blackboard> board = std::make_shared<bt::Blackboard>();
  FakePlanner* planner = nullptr;
};

const char* kComputePath = R"(<ComputePath start="{pose}" goal="{goal}" path="{path}"/>)";

TEST_F(LeafTest, compute_path_without_a_goal_fails_with_the_reason) {
  bt::Tree tree = build(kComputePath);
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"), "no goal to plan to");
  EXPECT_EQ(planner->requests, 0);
}

TEST_F(LeafTest, compute_path_runs_while_the_plan_is_computed_then_writes_it) {
  bt::Tree tree = build(kComputePath);
  board->set<robot::Pose2D>("goal", {4, 5, 0});
  EXPECT_EQ(tree.tick(), bt::Status::kRunning);
  EXPECT_EQ(planner->requests, 1);
  EXPECT_EQ(planner->from.x, 1);
  EXPECT_EQ(planner->to.y, 5);
  EXPECT_EQ(tree.tick(), bt::Status::kRunning);  // not ready: the tick only polls
  EXPECT_EQ(planner->requests, 1);
  planner->reply.success = true;
  planner->reply.path = {{1, 2}, {4, 5}};
  planner->ready = true;
  EXPECT_EQ(tree.tick(), bt::Status::kSuccess);
  ASSERT_NE(board->get<Path>("path"), nullptr);
  EXPECT_EQ(board->get<Path>("path")->size(), 2u);
}

TEST_F(LeafTest, a_replan_replaces_the_path_only_when_shorter_than_what_is_left) {
  bt::Tree tree = build(kComputePath);
  board->set<robot::Pose2D>("goal", {4, 5, 0});
  const auto plan = [&](Path path) {
    planner->reply.success = true;
    planner->reply.path = std::move(path);
    planner->ready = true;
    EXPECT_EQ(tree.tick(), bt::Status::kRunning);
    EXPECT_EQ(tree.tick(), bt::Status::kSuccess);
    return *board->get<Path>("path");
  };
  const Path first = {{1, 2}, {4, 2}, {4, 5}};  // 6 m
  EXPECT_EQ(plan(first).size(), 3u);
  // The other way round (4 + 3.2 m) is longer than the 6 m left: the robot keeps its way.
  EXPECT_EQ(plan({{1, 2}, {1, 6}, {4, 5}}).size(), 3u);
  EXPECT_EQ(board->get<Path>("path")->at(1).x, 4);
  // A straight line (4.2 m) is shorter: taken.
  EXPECT_EQ(plan({{1, 2}, {4, 5}}).size(), 2u);
  // A new goal: the next plan is taken whatever its length.
  board->set<robot::Pose2D>("goal", {9, 9, 0});
  EXPECT_EQ(plan({{1, 2}, {1, 9}, {9, 9}}).size(), 3u);
}

TEST_F(LeafTest, compute_path_failure_names_the_planner_s_reason) {
  bt::Tree tree = build(kComputePath);
  board->set<robot::Pose2D>("goal", {4, 5, 0});
  planner->reply.message = "goal: inside obstacle 2";
  planner->ready = true;
  EXPECT_EQ(tree.tick(), bt::Status::kRunning);
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  EXPECT_EQ(*board->get<std::string>("error"), "no path: goal: inside obstacle 2");
  EXPECT_EQ(board->get<Path>("path"), nullptr);
}

TEST_F(LeafTest, halting_compute_path_abandons_the_plan) {
  bt::Tree tree = build(kComputePath);
  board->set<robot::Pose2D>("goal", {4, 5, 0});
  EXPECT_EQ(tree.tick(), bt::Status::kRunning);
  tree.halt();
  EXPECT_EQ(planner->cancels, 1);
  EXPECT_EQ(tree.tick(), bt::Status::kRunning);  // entered anew: a new request
  EXPECT_EQ(planner->requests, 2);
}

TEST_F(LeafTest, goal_updated_reports_a_goal_written_during_its_run) {
  bt::Tree tree = build(R"(<GoalUpdated goal="{goal}"/>)");
  auto& goal = board->declare<robot::Pose2D>("goal");
  goal.set({1, 1, 0});
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);  // first tick of a run: records the goal
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  goal.set({2, 2, 0});
  EXPECT_EQ(tree.tick(), bt::Status::kSuccess);
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);  // reported once
  goal.set({3, 3, 0});
  board->advanceTick();  // a tick in which it was not ticked: the next one starts a run
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
}

TEST_F(LeafTest, has_goal_and_goal_succeeded_and_aborted_end_the_goal) {
  bt::Tree has = build(R"(<HasGoal goal="{goal}"/>)");
  EXPECT_EQ(has.tick(), bt::Status::kFailure);
  board->set<robot::Pose2D>("goal", {1, 1, 0});
  EXPECT_EQ(has.tick(), bt::Status::kSuccess);
  board->set<std::string>("error", "strayed 0.5 m from the path");
  bt::Tree abort = build(R"(<GoalAborted goal="{goal}" error="{error}"/>)");
  EXPECT_EQ(abort.tick(), bt::Status::kFailure);
  EXPECT_EQ(context.outcome, GoalOutcome::kAborted);
  EXPECT_EQ(context.message, "strayed 0.5 m from the path");
  EXPECT_EQ(has.tick(), bt::Status::kFailure);  // cleared
  board->set<robot::Pose2D>("goal", {1, 1, 0});
  bt::Tree done = build(R"(<GoalSucceeded goal="{goal}"/>)");
  EXPECT_EQ(done.tick(), bt::Status::kSuccess);
  EXPECT_EQ(context.outcome, GoalOutcome::kSucceeded);
  EXPECT_EQ(has.tick(), bt::Status::kFailure);
}

TEST_F(LeafTest, back_up_and_spin_run_their_distance_then_succeed) {
  bt::Tree back = build(R"(<BackUp backup_dist="0.1" backup_speed="0.1"/>)");
  int ticks = 0;
  while (back.tick() == bt::Status::kRunning) {
    EXPECT_DOUBLE_EQ(context.cmd.v, -0.1);
    ++ticks;
  }
  EXPECT_EQ(ticks, 60);  // 0.1 m at 0.1 m/s at 60 Hz
  bt::Tree spin = build(R"(<Spin spin_dist="-1.0" spin_speed="1.0"/>)");
  double turned = 0;
  while (spin.tick() == bt::Status::kRunning) turned += context.cmd.w / 60.0;
  EXPECT_NEAR(turned, -1.0, 1e-12);
}

TEST_F(LeafTest, is_bumped_reads_the_bumper) {
  bt::Tree tree = build("<IsBumped/>");
  EXPECT_EQ(tree.tick(), bt::Status::kFailure);
  context.bumper.pressed = true;
  EXPECT_EQ(tree.tick(), bt::Status::kSuccess);
}

TEST(PathChecker, a_robot_hugging_furniture_plans_from_the_nearest_free_point_and_its_path_counts) {
  planning::Problem world;
  world.bounds = {0, 10, 0, 10};
  world.obstacles = {{{5, 5}, 1.0}};
  world.robot_radius = 0.2;
  world.clearance = kDefaultClearance;
  const PathChecker checker(world);
  ASSERT_TRUE(checker.fits());
  // 1.2 m from the centre: the disc touches the table but is inside the clearance.
  const planning::Point2 hugging{6.2, 5.0};
  EXPECT_FALSE(checker.isPointFree(hugging));
  const planning::Point2 start = checker.freeStart(hugging);
  EXPECT_TRUE(checker.isPointFree(start));
  EXPECT_LE(planning::distance(start, hugging), 0.06);
  // A path from where the robot stands counts as free when the rest of it is.
  EXPECT_TRUE(checker.isPathFree({hugging, {8, 5}, {8, 8}}, 0));
  EXPECT_FALSE(checker.isPathFree({hugging, {8, 5}, {5, 5.5}}, 0));
  // Walls: the bounds shrunk by radius + clearance.
  EXPECT_FALSE(checker.isPointFree({0.2, 5}));
  world.robot_radius = 5.0;
  EXPECT_FALSE(PathChecker(world).fits());
}

TEST(InProcessPlanner, plans_on_its_worker_thread_and_reports_once) {
  planning::Problem world;
  world.clearance = kDefaultClearance;
  world.bounds = {0, 10, 0, 10};
  world.obstacles = {{{5, 5}, 1.0}};
  world.robot_radius = 0.2;
  InProcessPlanner planner(world, planning::PlannerOptions{});
  planner.request({1, 1}, {9, 9});
  PlanReply reply;
  // Poll as a tree would (a safety bound only: nothing here is timed).
  for (int i = 0; i < 10000 && !planner.poll(reply); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(reply.success) << reply.message;
  EXPECT_EQ(reply.path.back().x, 9);
  EXPECT_TRUE(PathChecker(world).isPathFree(reply.path, 0));
  EXPECT_FALSE(planner.poll(reply));                                 // reported once
  EXPECT_FALSE(PathChecker(world).isPathFree({{1, 5}, {9, 5}}, 0));  // through the grown disc
}

TEST(InProcessPlanner, a_goal_in_a_grown_rectangle_is_refused_naming_it) {
  planning::Problem world;
  world.clearance = kDefaultClearance;
  world.bounds = {0, 10, 0, 10};
  world.rectangles = {{2, 2, 3, 3}};
  world.robot_radius = 0.2;
  const InProcessPlanner planner(world, planning::PlannerOptions{},
                                 InProcessPlanner::Mode::kInline);
  const PlanReply reply = planner.planNow({1, 1}, {3.1, 2.5}, 1);
  EXPECT_FALSE(reply.success);
  EXPECT_EQ(reply.message.rfind("goal: inside rectangles[0] (grown by robot_radius + clearance", 0),
            0u)
      << reply.message;
}

}  // namespace
TEST(InProcessPlanner, refuses_a_robot_size_the_library_refuses_naming_the_field) {
  planning::Problem world;
  world.clearance = kDefaultClearance;
  world.bounds = {0, 10, 0, 10};
  for (const auto& [radius, clearance, field] :
       {std::tuple{std::nan(""), 0.05, "robot_radius"}, std::tuple{0.2, -1.0, "clearance"},
        std::tuple{6.0, 0.05, "robot_radius"}}) {
    world.robot_radius = radius;
    world.clearance = clearance;
    try {
      InProcessPlanner planner(world, planning::PlannerOptions{}, InProcessPlanner::Mode::kInline);
      ADD_FAILURE() << "accepted robot_radius " << radius << ", clearance " << clearance;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(std::string("planner: ") + field, 0), 0u) << e.what();
    }
  }
}

}  // namespace roomba_rrt::navigation
