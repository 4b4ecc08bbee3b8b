#include "roomba_rrt/planning/validate.h"

#include <cmath>
#include <string>
#include <string_view>

#include "roomba_rrt/planning/limits.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::planning {
namespace {

using util::entry;
using util::InvalidInput;
using util::member;
using util::show;

using util::requireFinite;

// Both of the above, for a coordinate.
void requireCoordinate(std::string_view field, double v) {
  requireFinite(field, v);
  util::requireInRange(field, v, -kMaxCoordinate, kMaxCoordinate, "m");
}

bool withinCoordinateRange(double v) { return std::abs(v) <= kMaxCoordinate; }

// A field's path is only spelled out once it has an error to report.
void requirePointFinite(const char* field, const Point2& p) {
  if (std::isfinite(p.x) && std::isfinite(p.y)) return;
  requireFinite(member(field, "x"), p.x);
  requireFinite(member(field, "y"), p.y);
}

void requirePlaceable(const char* field, const Point2& p, const Problem& problem) {
  const double margin = robotMargin(problem);
  // " (grown by robot_radius + clearance 0.17)" when the robot has a size, "" for a point.
  const auto grown = [&] {
    return margin > 0 ? " (grown by robot_radius + clearance " + show(margin) + ")" : "";
  };
  if (!contains(shrink(problem.bounds, margin), p)) {
    throw InvalidInput(
        field, "(" + show(p.x) + ", " + show(p.y) + ") is outside the bounds" +
                   (margin > 0 ? " shrunk by robot_radius + clearance " + show(margin) : ""));
  }
  for (std::size_t i = 0; i < problem.obstacles.size(); ++i) {
    if (geometry::withinMargin(problem.obstacles[i], p, margin)) {
      throw InvalidInput(field, "inside obstacle " + std::to_string(i) + grown());
    }
  }
  for (std::size_t i = 0; i < problem.rectangles.size(); ++i) {
    if (geometry::withinMargin(problem.rectangles[i], p, margin)) {
      throw InvalidInput(field, "inside " + entry("rectangles", i) + grown());
    }
  }
  if (problem.map && !problem.map->discFree(p, problem.map->disc(margin))) {
    throw InvalidInput(field, "(" + show(p.x) + ", " + show(p.y) + ") is in a wall of the map: " +
                                  (problem.map->unknownIsFree() ? "an occupied cell"
                                                                : "an occupied or unknown cell") +
                                  grown());
  }
}

// Bounds: finite, in range, not empty or inverted, not too thin.
void validateBounds(const Bounds& b) {
  for (const auto& [field, value] : {std::pair<const char*, double>{"bounds.x_min", b.x_min},
                                     {"bounds.x_max", b.x_max},
                                     {"bounds.y_min", b.y_min},
                                     {"bounds.y_max", b.y_max}}) {
    requireCoordinate(field, value);
  }
  if (!(b.x_min < b.x_max)) {
    throw InvalidInput("bounds", "x_min must be < x_max (empty or inverted bounds)");
  }
  if (!(b.y_min < b.y_max)) {
    throw InvalidInput("bounds", "y_min must be < y_max (empty or inverted bounds)");
  }
  if (b.x_max - b.x_min < kMinBoundsExtent || b.y_max - b.y_min < kMinBoundsExtent) {
    throw InvalidInput("bounds",
                       "width (x_max - x_min) and height (y_max - y_min) must be at least " +
                           show(kMinBoundsExtent) + " m, got " + show(b.x_max - b.x_min) + " x " +
                           show(b.y_max - b.y_min));
  }
}

// Discs: centre finite and in range, radius finite and in [0, kMaxLength].
void validateObstacles(const std::vector<Circle>& obstacles) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const Circle& c = obstacles[i];
    if (withinCoordinateRange(c.center.x) && withinCoordinateRange(c.center.y) && c.radius >= 0 &&
        c.radius <= kMaxLength) {
      continue;  // false for NaN
    }
    const std::string field = entry("obstacles", i);
    const std::string center = member(field, "center");
    requireFinite(member(center, "x"), c.center.x);
    requireFinite(member(center, "y"), c.center.y);
    util::requireInRange(member(center, "x"), c.center.x, -kMaxCoordinate, kMaxCoordinate, "m");
    util::requireInRange(member(center, "y"), c.center.y, -kMaxCoordinate, kMaxCoordinate, "m");
    requireFinite(member(field, "radius"), c.radius);
    util::requireInRange(member(field, "radius"), c.radius, 0, kMaxLength, "m");
  }
}

// NaN, inverted or empty rectangles, named by field ("rectangles[2].max_x: ...").
void validateRectangles(const std::vector<Rectangle>& rectangles) {
  for (std::size_t i = 0; i < rectangles.size(); ++i) {
    const Rectangle& r = rectangles[i];
    if (withinCoordinateRange(r.min_x) && withinCoordinateRange(r.min_y) &&
        withinCoordinateRange(r.max_x) && withinCoordinateRange(r.max_y) && r.min_x < r.max_x &&
        r.min_y < r.max_y) {
      continue;  // false for NaN
    }
    const std::string field = entry("rectangles", i);
    for (const auto& [key, value] : {std::pair<const char*, double>{"min_x", r.min_x},
                                     {"min_y", r.min_y},
                                     {"max_x", r.max_x},
                                     {"max_y", r.max_y}}) {
      requireCoordinate(member(field, key), value);
    }
    if (!(r.min_x < r.max_x)) {
      throw InvalidInput(member(field, "max_x"), "must be > min_x, got " + show(r.max_x) +
                                                     " <= " + show(r.min_x) +
                                                     " (an empty or inverted rectangle)");
    }
    throw InvalidInput(member(field, "max_y"), "must be > min_y, got " + show(r.max_y) +
                                                   " <= " + show(r.min_y) +
                                                   " (an empty or inverted rectangle)");
  }
}

// The robot's size: finite, not negative, and small enough to fit in the bounds.
void validateRobotSize(const Problem& problem) {
  for (const auto& [field, value] :
       {std::pair<const char*, double>{"robot_radius", problem.robot_radius},
        {"clearance", problem.clearance}}) {
    requireFinite(field, value);
    util::requireInRange(field, value, 0, kMaxLength, "m");
  }
  const Bounds inner = shrink(problem.bounds, robotMargin(problem));
  if (!(inner.x_min <= inner.x_max && inner.y_min <= inner.y_max)) {
    throw InvalidInput("robot_radius", "a disc of robot_radius + clearance " +
                                           show(robotMargin(problem)) +
                                           " does not fit in the bounds");
  }
}

void validateProblem(const Problem& problem) {
  validateBounds(problem.bounds);
  if (problem.obstacles.size() + problem.rectangles.size() >
      static_cast<std::size_t>(kMaxObstacles)) {
    throw InvalidInput("obstacles", "at most " + std::to_string(kMaxObstacles) +
                                        " obstacles and rectangles together, got " +
                                        std::to_string(problem.obstacles.size()) + " + " +
                                        std::to_string(problem.rectangles.size()));
  }
  validateObstacles(problem.obstacles);
  validateRectangles(problem.rectangles);
  validateRobotSize(problem);
  requirePointFinite("start", problem.start);
  requirePointFinite("goal", problem.goal);
  requirePlaceable("start", problem.start, problem);
  requirePlaceable("goal", problem.goal, problem);
}

void validateOptions(const PlannerOptions& o, int max_iterations_cap) {
  requireFinite("step", o.step);
  util::requireInRange("step", o.step, kMinStep, kMaxLength, "m");
  requireFinite("goal_bias", o.goal_bias);
  if (o.goal_bias < 0 || o.goal_bias > 1) {
    util::failRule("goal_bias", "in [0, 1]", o.goal_bias);
  }
  if (o.max_iterations < 1) {
    throw InvalidInput("max_iterations", "must be >= 1, got " + std::to_string(o.max_iterations));
  }
  if (o.max_iterations > max_iterations_cap) {
    throw InvalidInput("max_iterations", std::to_string(o.max_iterations) +
                                             " is above the cap of " +
                                             std::to_string(max_iterations_cap));
  }
  requireFinite("goal_tolerance", o.goal_tolerance);
  util::requireInRange("goal_tolerance", o.goal_tolerance, 0, kMaxLength, "m");
  requireFinite("max_planning_time", o.max_planning_time);
  util::requireInRange("max_planning_time", o.max_planning_time, 0, kMaxPlanningTime, "s");
  if (o.max_rejection_tries < 1) throw InvalidInput("max_rejection_tries", "must be >= 1");
  if (o.smoothing_tries < 0) throw InvalidInput("smoothing_tries", "must be >= 0");
}

// region_astar searches a map's cells: a map, and nothing else in the way.
void validateAlgorithm(const Problem& problem, const PlannerOptions& o) {
  if (o.algorithm != Algorithm::kRegionAStar) return;
  if (!problem.map) {
    throw InvalidInput("algorithm",
                       "region_astar plans on a map (scenario 'map', make_plan), "
                       "and this problem has none; rrt, rrt_connect and rrt_star "
                       "plan among circles and rectangles");
  }
  if (!problem.obstacles.empty()) {
    throw InvalidInput("obstacles", "region_astar plans on the map's cells alone, got " +
                                        std::to_string(problem.obstacles.size()) +
                                        " circles (rrt_connect plans among them)");
  }
  if (!problem.rectangles.empty()) {
    throw InvalidInput("rectangles", "region_astar plans on the map's cells alone, got " +
                                         std::to_string(problem.rectangles.size()) +
                                         " rectangles (rrt_connect plans among them)");
  }
}

}  // namespace

void validate(const Problem& problem, const PlannerOptions& options, int max_iterations_cap) {
  validateProblem(problem);
  validateOptions(options, max_iterations_cap);
  validateAlgorithm(problem, options);
}

}  // namespace roomba_rrt::planning
