#include "roomba_rrt/navigation/path_planner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "roomba_rrt/planning/planner.h"

namespace roomba_rrt::navigation {
namespace {

using planning::Point2;

planning::Problem problemFrom(const NavWorld& world) {
  planning::Problem problem;
  problem.obstacles = world.circles;
  problem.rectangles = world.rectangles;
  problem.bounds = world.bounds;
  problem.robot_radius = world.robot_radius;
  problem.clearance = world.clearance;
  return problem;
}

}  // namespace

NavWorld navWorldFrom(const world::World& world, double clearance) {
  NavWorld nav;
  nav.bounds = {0.0, world.width, 0.0, world.height};
  nav.circles = world.circles;
  nav.rectangles = world.rectangles;
  nav.robot_radius = world.robot_radius;
  nav.clearance = clearance;
  return nav;
}

InProcessPlanner::InProcessPlanner(NavWorld world, const planning::PlannerOptions& options,
                                   Mode mode, PlanFunction plan_function)
    : world_(std::move(world)),
      options_(options),
      mode_(mode),
      plan_function_(std::move(plan_function)),
      base_(problemFrom(world_)),
      checker_(world_.circles, planning::CollisionCheck::kSegments, world_.rectangles,
               planning::robotMargin(base_)),
      shrunk_(planning::shrink(world_.bounds, planning::robotMargin(base_))) {
  // The world is checked by the library as a problem whose start and goal are the room's centre
  // (furniture left out: the centre may be inside it): bounds, options and the robot's size
  // (finite, in range, fitting in the room) with the library's own messages.
  planning::Problem probe = base_;
  probe.obstacles.clear();
  probe.rectangles.clear();
  probe.start = probe.goal = {0.5 * (world_.bounds.x_min + world_.bounds.x_max),
                              0.5 * (world_.bounds.y_min + world_.bounds.y_max)};
  try {
    planning::validate(probe, options_);
  } catch (const util::InvalidInput& invalid) {
    throw invalid.in("planner");
  }
  if (!(shrunk_.x_min < shrunk_.x_max && shrunk_.y_min < shrunk_.y_max)) {
    throw util::InvalidInput("robot_radius", "the robot's disc does not fit in the room",
                             "planner");
  }
  if (mode_ == Mode::kThread) worker_ = std::thread([this] { work(); });
}

InProcessPlanner::~InProcessPlanner() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
}

PlanReply InProcessPlanner::planNow(const Point2& start, const Point2& goal,
                                    std::uint32_t seed) const {
  const Point2 from = freeStart(start);
  if (plan_function_) {
    PlanReply reply = plan_function_(from, goal, seed);
    if (reply.success) finishPath(start, goal, reply.path);
    return reply;
  }
  PlanReply reply;
  planning::Problem problem = base_;
  problem.start = from;
  problem.goal = goal;
  planning::PlannerOptions options = options_;
  options.seed = seed;
  planning::PlanResult result = planning::plan(problem, options);
  reply.planning_ms = result.planning_time * 1e3;
  reply.success = result.success;
  reply.message = result.message;
  if (result.success) {
    reply.path = std::move(result.path);
    finishPath(start, goal, reply.path);
  }
  return reply;
}

Point2 InProcessPlanner::freeStart(const Point2& start) const {
  // A start inside the grown obstacles (the robot hugging furniture a little closer than the
  // clearance, or pushed there by a bump) is planned from the nearest free point around it.
  if (isPointFree(start)) return start;
  for (int ring = 1; ring <= 25; ++ring) {
    const double r = 0.01 * ring;
    for (int k = 0; k < 32; ++k) {
      const double a = 2.0 * M_PI * k / 32;
      const Point2 p{start.x + r * std::cos(a), start.y + r * std::sin(a)};
      if (isPointFree(p)) return p;
    }
  }
  return start;
}

void finishPath(const Point2& start, const Point2& goal, Path& path) {
  if (!path.empty() && (path.front().x != start.x || path.front().y != start.y)) {
    path.insert(path.begin(), start);
  }
  if (path.empty() || planning::distance(path.back(), goal) > 0) path.push_back(goal);
}

void InProcessPlanner::request(const Point2& start, const Point2& goal) {
  if (mode_ == Mode::kInline) {
    result_ = planNow(start, goal, options_.seed + requests_++);
    wanted_ = done_ + 1;
    done_ = wanted_.load();
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++requested_;
    start_ = start;
    goal_ = goal;
    wanted_ = requested_;
  }
  wake_.notify_one();
}

bool InProcessPlanner::poll(PlanReply& reply) {
  const std::uint64_t wanted = wanted_.load(std::memory_order_relaxed);
  if (wanted == 0 || done_.load(std::memory_order_acquire) != wanted) return false;
  std::swap(reply, result_);
  wanted_.store(0, std::memory_order_relaxed);  // reported once
  return true;
}

void InProcessPlanner::cancel() { wanted_.store(0, std::memory_order_relaxed); }

void InProcessPlanner::work() {
  std::uint64_t seen = 0;
  for (;;) {
    Point2 start, goal;
    std::uint64_t generation = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || requested_ != seen; });
      if (stop_) return;
      generation = seen = requested_;
      start = start_;
      goal = goal_;
    }
    // The n-th request plans with seed + n - 1, as in kInline.
    PlanReply reply =
        planNow(start, goal, options_.seed + static_cast<std::uint32_t>(generation - 1));
    std::lock_guard<std::mutex> lock(mutex_);
    if (generation != requested_) continue;  // superseded: plan the newer request
    result_ = std::move(reply);
    done_.store(generation, std::memory_order_release);
  }
}

bool InProcessPlanner::isPointFree(const Point2& p) const {
  return planning::contains(shrunk_, p) && checker_.isFree(p);
}

bool InProcessPlanner::isPathFree(const Path& path, std::size_t from) const {
  // A path planned from a start inside the grown obstacles begins with that start (planNow).
  if (from == 0 && path.size() > 1 && !isPointFree(path[0])) from = 1;
  for (std::size_t i = from; i < path.size(); ++i) {
    if (!isPointFree(path[i])) return false;
    if (i + 1 < path.size() && !checker_.isSegmentFree(path[i], path[i + 1])) return false;
  }
  return true;
}

}  // namespace roomba_rrt::navigation
