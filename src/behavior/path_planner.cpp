#include "roomba_rrt/behavior/path_planner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "roomba_rrt/planning/planner.h"

namespace roomba_rrt::behavior {
namespace {

using planning::Circle;
using planning::Point2;

bool insideGrown(const sim::Rectangle& r, double margin, const Point2& p) {
  const double dx = std::max({r.min_x - p.x, 0.0, p.x - r.max_x});
  const double dy = std::max({r.min_y - p.y, 0.0, p.y - r.max_y});
  return dx * dx + dy * dy <= margin * margin;
}

/// Discs centred on pieces (at most `step` long) of the edges of `r`, of radius half a piece +
/// `margin`: every point within `margin` of the rectangle's outline lies in one of them.
void coverOutline(const sim::Rectangle& r, double margin, double step, std::vector<Circle>& out) {
  const auto edge = [&](Point2 a, Point2 b) {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int n = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) / n;
      out.push_back({{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, 0.5 * length / n + margin});
    }
  };
  edge({r.min_x, r.min_y}, {r.max_x, r.min_y});
  edge({r.max_x, r.min_y}, {r.max_x, r.max_y});
  edge({r.max_x, r.max_y}, {r.min_x, r.max_y});
  edge({r.min_x, r.max_y}, {r.min_x, r.min_y});
}

}  // namespace

NavWorld navWorldFrom(const sim::World& world, double clearance) {
  NavWorld nav;
  nav.bounds = {0.0, world.width, 0.0, world.height};
  for (const sim::Circle& c : world.circles) nav.circles.push_back({{c.x, c.y}, c.radius});
  nav.rectangles = world.rectangles;
  nav.robot_radius = world.robot_radius;
  nav.clearance = clearance;
  return nav;
}

InProcessPlanner::InProcessPlanner(NavWorld world, const planning::PlannerOptions& options,
                                   Mode mode)
    : world_(std::move(world)), options_(options), mode_(mode) {
  const double margin = world_.robot_radius + world_.clearance;
  if (!(std::isfinite(margin) && world_.robot_radius >= 0 && world_.clearance >= 0)) {
    throw std::invalid_argument("robot_radius and clearance must be finite and >= 0");
  }
  if (!(std::isfinite(world_.rectangle_cover_step) && world_.rectangle_cover_step > 0)) {
    throw std::invalid_argument("rectangle_cover_step must be finite and > 0");
  }
  for (const Circle& c : world_.circles) grown_.push_back({c.center, c.radius + margin});
  for (const sim::Rectangle& r : world_.rectangles) {
    coverOutline(r, margin, world_.rectangle_cover_step, grown_);
  }
  shrunk_ = {world_.bounds.x_min + margin, world_.bounds.x_max - margin,
             world_.bounds.y_min + margin, world_.bounds.y_max - margin};
  planning::Problem probe{
      {shrunk_.x_min, shrunk_.y_min}, {shrunk_.x_min, shrunk_.y_min}, {}, shrunk_};
  planning::PlannerOptions check = options_;
  const std::string problem = planning::validate(probe, check);
  if (!problem.empty()) throw std::invalid_argument("planner: " + problem);
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
  PlanReply reply;
  const double margin = world_.robot_radius + world_.clearance;
  for (std::size_t i = 0; i < world_.rectangles.size(); ++i) {
    if (insideGrown(world_.rectangles[i], margin, goal)) {
      reply.message = "goal: inside rectangle " + std::to_string(i) +
                      " (grown by the robot's radius and clearance)";
      return reply;
    }
  }
  // A start inside the grown obstacles (the robot hugging furniture a little closer than the
  // clearance, or pushed there by a bump) is planned from the nearest free point around it.
  Point2 from = start;
  if (!isPointFree(start)) {
    bool found = false;
    for (int ring = 1; ring <= 25 && !found; ++ring) {
      const double r = 0.01 * ring;
      for (int k = 0; k < 32 && !found; ++k) {
        const double a = 2.0 * M_PI * k / 32;
        const Point2 p{start.x + r * std::cos(a), start.y + r * std::sin(a)};
        if (isPointFree(p)) {
          from = p;
          found = true;
        }
      }
    }
  }
  planning::Problem problem{from, goal, grown_, shrunk_};
  planning::PlannerOptions options = options_;
  options.seed = seed;
  planning::PlanResult result = planning::plan(problem, options);
  reply.planning_ms = result.planning_time * 1e3;
  reply.success = result.success;
  reply.message = result.message;
  if (result.success) {
    reply.path = std::move(result.path);
    if (from.x != start.x || from.y != start.y) reply.path.insert(reply.path.begin(), start);
    if (reply.path.empty() || planning::distance(reply.path.back(), goal) > 0) {
      reply.path.push_back(goal);
    }
  }
  return reply;
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
  if (!planning::contains(shrunk_, p)) return false;
  for (const Circle& c : grown_) {
    if (planning::contains(c, p)) return false;
  }
  return true;
}

bool InProcessPlanner::isPathFree(const Path& path, std::size_t from) const {
  const double margin = world_.robot_radius + world_.clearance;
  // A path planned from a start inside the grown obstacles begins with that start (planNow).
  if (from == 0 && path.size() > 1 && !isPointFree(path[0])) from = 1;
  for (std::size_t i = from; i + 1 < path.size(); ++i) {
    const Point2& a = path[i];
    const Point2& b = path[i + 1];
    const double min_x = std::min(a.x, b.x), max_x = std::max(a.x, b.x);
    const double min_y = std::min(a.y, b.y), max_y = std::max(a.y, b.y);
    for (const Circle& c : grown_) {
      // A disc outside the segment's box grown by its radius cannot meet it (exact test after).
      if (c.center.x + c.radius < min_x || c.center.x - c.radius > max_x ||
          c.center.y + c.radius < min_y || c.center.y - c.radius > max_y) {
        continue;
      }
      if (planning::segmentMeetsCircle(a, b, c)) return false;
    }
  }
  for (std::size_t i = from; i < path.size(); ++i) {
    if (!planning::contains(shrunk_, path[i])) return false;
    for (const sim::Rectangle& r : world_.rectangles) {
      if (insideGrown(r, margin, path[i])) return false;
    }
  }
  return true;
}

}  // namespace roomba_rrt::behavior
