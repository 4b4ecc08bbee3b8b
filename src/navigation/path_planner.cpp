#include "roomba_rrt/navigation/path_planner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "roomba_rrt/planning/planner.h"

namespace roomba_rrt::navigation {

using planning::Point2;

InProcessPlanner::InProcessPlanner(planning::Problem world, const planning::PlannerOptions& options,
                                   Mode mode, PlanFunction plan_function)
    : checker_(std::move(world)),
      options_(options),
      mode_(mode),
      plan_function_(std::move(plan_function)) {
  validate(checker_.world(), options_);
  if (mode_ == Mode::kThread) worker_ = std::thread([this] { work(); });
}

void InProcessPlanner::validate(const planning::Problem& world,
                                const planning::PlannerOptions& options) {
  // The world is checked by the library as a problem whose start and goal are the room's centre
  // (furniture and map left out: the centre may be inside them): bounds, options and the robot's
  // size (finite, in range, fitting in the room) with the library's own messages.
  planning::Problem probe = world;
  probe.obstacles.clear();
  probe.rectangles.clear();
  probe.map = nullptr;
  probe.start = probe.goal = {0.5 * (probe.bounds.x_min + probe.bounds.x_max),
                              0.5 * (probe.bounds.y_min + probe.bounds.y_max)};
  try {
    planning::validate(probe, options);
  } catch (const util::InvalidInput& invalid) {
    throw invalid.in("planner");
  }
  if (!PathChecker(world).fits()) {
    throw util::InvalidInput("robot_radius", "the robot's disc does not fit in the room",
                             "planner");
  }
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
  const Point2 from = checker_.freeStart(start);
  if (plan_function_) {
    PlanReply reply = plan_function_(from, goal, seed);
    if (reply.success) finishPath(start, goal, reply.path);
    return reply;
  }
  PlanReply reply;
  planning::Problem problem = checker_.world();
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

}  // namespace roomba_rrt::navigation
