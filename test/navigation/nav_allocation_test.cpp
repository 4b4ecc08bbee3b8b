// Ticks allocate nothing: the lab tree, and the navigation tree while it follows a path and
// replans on the planner's worker thread (this thread only polls). Counts operator new on the
// test's thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <new>
#include <thread>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/robot/unicycle.h"

namespace {
thread_local long allocations = 0;
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace roomba_rrt::navigation {
namespace {

TEST(TickAllocations, the_lab_tree_ticks_without_allocating) {
  behavior::RoombaBt bt(behavior::RoombaParams{}, 1);
  bt.tick({});
  const long before = allocations;
  for (int i = 0; i < 36000; ++i) bt.tick({i % 997 == 0, false, false});
  EXPECT_EQ(allocations - before, 0);
}

/// Forwards to a planner and counts the plans it reports.
class CountingPlanner final : public PathPlanner {
 public:
  CountingPlanner(std::unique_ptr<PathPlanner> planner, std::atomic<int>& count)
      : planner_(std::move(planner)), count_(count) {}
  void request(const planning::Point2& start, const planning::Point2& goal) override {
    planner_->request(start, goal);
  }
  bool poll(PlanReply& reply) override {
    if (!planner_->poll(reply)) return false;
    ++count_;
    return true;
  }
  void cancel() override { planner_->cancel(); }

 private:
  std::unique_ptr<PathPlanner> planner_;
  std::atomic<int>& count_;
};

TEST(TickAllocations, the_navigation_tree_follows_and_replans_without_allocating) {
  planning::Problem world;
  world.clearance = kDefaultClearance;
  world.bounds = {0, 10, 0, 10};
  world.obstacles = {{{5, 5.6}, 0.3}};
  world.robot_radius = 0.17;
  NavLeafConfig config = inProcessNavConfig(world);
  // Counts the plans that arrive (a replan that is not shorter than what is left of the current
  // path is not written to the blackboard, so the path's writes do not count them).
  auto arrived = std::make_shared<std::atomic<int>>(0);
  config.planners = [planners = config.planners, arrived] {
    return std::make_unique<CountingPlanner>(planners(), *arrived);
  };
  NavBt nav(config, 1, ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml");
  robot::Pose2D pose{0.5, 5.0, 0.0};
  nav.setGoal({9.5, 5.0, 0.0});
  // Until the first plan arrives and the follower runs (allocations allowed: the first path).
  for (int i = 0; i < 10000 && nav.stateName() != "FollowPath"; ++i) {
    pose = robot::integrateArc(pose, nav.tick({}, pose), 1.0 / 60);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // let the worker plan
  }
  ASSERT_EQ(nav.stateName(), "FollowPath");
  // Drive 20 s: ten replans at 0.5 Hz. Each path is built on the worker thread and swapped in;
  // the old one goes back to the worker, which frees it.
  const auto& path = nav.tree().blackboard().declare<Path>("path");
  const int plans = arrived->load();
  const long before = allocations;
  long following = 0;
  for (int i = 0; i < 20 * 60; ++i) {
    pose = robot::integrateArc(pose, nav.tick({}, pose), 1.0 / 60);
    following += nav.stateName() == "FollowPath";
    // Give the worker time to finish each replan (not a timing check: only so that replans
    // arrive during the loop).
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  const long allocated = allocations - before;  // before any failure message allocates
  EXPECT_GE(arrived->load() - plans, 3);        // replans arrived and were taken or dropped
  EXPECT_GE(path.writes, 1u);
  EXPECT_EQ(nav.outcome(), GoalOutcome::kActive);
  EXPECT_GT(following, 20 * 60 - 30);
  EXPECT_EQ(allocated, 0);
}

}  // namespace
}  // namespace roomba_rrt::navigation
