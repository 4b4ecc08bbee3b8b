#include "roomba_rrt/planning/validate.h"

#include <cmath>
#include <sstream>

#include "roomba_rrt/planning/limits.h"

namespace roomba_rrt::planning {
namespace {

std::string show(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// "field: NaN or infinite" for the first non-finite value, "" otherwise.
std::string checkFinite(const std::string& field, double v) {
  return std::isfinite(v) ? "" : field + ": must be finite (got " + show(v) + ")";
}

// "field: must be in [lo, hi] <unit> (got v)" when v (finite) is outside, "" otherwise.
std::string checkRange(const char* field, double v, double lo, double hi, const char* unit = "m") {
  if (v >= lo && v <= hi) return "";
  return std::string(field) + ": must be in [" + show(lo) + ", " + show(hi) + "] " + unit +
         " (got " + show(v) + ")";
}

bool withinCoordinateRange(double v) { return std::abs(v) <= kMaxCoordinate; }

// plan() validates every call and a lab solve takes some 20 us, so the checks of valid input
// build no strings: a field's name is only spelled out once it has an error to report.
std::string checkPointFinite(const std::string& field, const Point2& p) {
  if (std::isfinite(p.x) && std::isfinite(p.y)) return "";
  std::string error = checkFinite(field + ".x", p.x);
  return error.empty() ? checkFinite(field + ".y", p.y) : error;
}

std::string checkPlaceable(const std::string& field, const Point2& p, const Problem& problem) {
  const double margin = robotMargin(problem);
  // " (grown by robot_radius + clearance 0.17)" when the robot has a size, "" for a point.
  const auto grown = [&] {
    return margin > 0 ? " (grown by robot_radius + clearance " + show(margin) + ")" : "";
  };
  if (!contains(shrink(problem.bounds, margin), p)) {
    return field + ": (" + show(p.x) + ", " + show(p.y) + ") is outside the bounds" +
           (margin > 0 ? " shrunk by robot_radius + clearance " + show(margin) : "");
  }
  for (std::size_t i = 0; i < problem.obstacles.size(); ++i) {
    if (geometry::withinMargin(problem.obstacles[i], p, margin)) {
      return field + ": inside obstacle " + std::to_string(i) + grown();
    }
  }
  for (std::size_t i = 0; i < problem.rectangles.size(); ++i) {
    if (geometry::withinMargin(problem.rectangles[i], p, margin)) {
      return field + ": inside rectangles[" + std::to_string(i) + "]" + grown();
    }
  }
  return "";
}

// NaN, inverted or empty rectangles, named by field ("rectangles[2].max_x: ...").
std::string checkRectangles(const std::vector<Rectangle>& rectangles) {
  for (std::size_t i = 0; i < rectangles.size(); ++i) {
    const Rectangle& r = rectangles[i];
    if (withinCoordinateRange(r.min_x) && withinCoordinateRange(r.min_y) &&
        withinCoordinateRange(r.max_x) && withinCoordinateRange(r.max_y) && r.min_x < r.max_x &&
        r.min_y < r.max_y) {
      continue;  // false for NaN
    }
    const std::string field = "rectangles[" + std::to_string(i) + "]";
    for (const auto& [key, value] : {std::pair<const char*, double>{".min_x", r.min_x},
                                     {".min_y", r.min_y},
                                     {".max_x", r.max_x},
                                     {".max_y", r.max_y}}) {
      if (auto error = checkFinite(field + key, value); !error.empty()) return error;
      const std::string name = field + key;
      if (auto error = checkRange(name.c_str(), value, -kMaxCoordinate, kMaxCoordinate);
          !error.empty()) {
        return error;
      }
    }
    if (!(r.min_x < r.max_x)) {
      return field + ".max_x: must be > min_x (got " + show(r.max_x) + " <= " + show(r.min_x) +
             ": an empty or inverted rectangle)";
    }
    return field + ".max_y: must be > min_y (got " + show(r.max_y) + " <= " + show(r.min_y) +
           ": an empty or inverted rectangle)";
  }
  return "";
}

// The robot's size: finite, not negative, and small enough to fit in the bounds.
std::string checkRobotSize(const Problem& problem) {
  for (const auto& [field, value] :
       {std::pair<const char*, double>{"robot_radius", problem.robot_radius},
        {"clearance", problem.clearance}}) {
    if (auto error = checkFinite(field, value); !error.empty()) return error;
    if (auto error = checkRange(field, value, 0, kMaxLength); !error.empty()) return error;
  }
  const Bounds inner = shrink(problem.bounds, robotMargin(problem));
  if (!(inner.x_min <= inner.x_max && inner.y_min <= inner.y_max)) {
    return "robot_radius: a disc of robot_radius + clearance " + show(robotMargin(problem)) +
           " does not fit in the bounds";
  }
  return "";
}

std::string validateProblem(const Problem& problem) {
  const Bounds& b = problem.bounds;
  for (const auto& [field, value] : {std::pair<const char*, double>{"bounds.x_min", b.x_min},
                                     {"bounds.x_max", b.x_max},
                                     {"bounds.y_min", b.y_min},
                                     {"bounds.y_max", b.y_max}}) {
    if (auto error = checkFinite(field, value); !error.empty()) return error;
    if (auto error = checkRange(field, value, -kMaxCoordinate, kMaxCoordinate); !error.empty()) {
      return error;
    }
  }
  if (!(b.x_min < b.x_max)) return "bounds: x_min must be < x_max (empty or inverted bounds)";
  if (!(b.y_min < b.y_max)) return "bounds: y_min must be < y_max (empty or inverted bounds)";
  if (b.x_max - b.x_min < kMinBoundsExtent || b.y_max - b.y_min < kMinBoundsExtent) {
    return "bounds: width (x_max - x_min) and height (y_max - y_min) must be at least " +
           show(kMinBoundsExtent) + " m (got " + show(b.x_max - b.x_min) + " x " +
           show(b.y_max - b.y_min) + ")";
  }
  if (problem.obstacles.size() + problem.rectangles.size() >
      static_cast<std::size_t>(kMaxObstacles)) {
    return "obstacles: at most " + std::to_string(kMaxObstacles) +
           " obstacles and rectangles together (got " + std::to_string(problem.obstacles.size()) +
           " + " + std::to_string(problem.rectangles.size()) + ")";
  }
  for (std::size_t i = 0; i < problem.obstacles.size(); ++i) {
    const Circle& c = problem.obstacles[i];
    const bool valid = withinCoordinateRange(c.center.x) && withinCoordinateRange(c.center.y) &&
                       c.radius >= 0 && c.radius <= kMaxLength;  // false for NaN
    if (valid) continue;
    const std::string field = "obstacles[" + std::to_string(i) + "]";
    if (auto error = checkPointFinite(field + ".center", c.center); !error.empty()) return error;
    for (const auto& [axis, value] :
         {std::pair<const char*, double>{".center.x", c.center.x}, {".center.y", c.center.y}}) {
      const std::string name = field + axis;
      if (auto error = checkRange(name.c_str(), value, -kMaxCoordinate, kMaxCoordinate);
          !error.empty()) {
        return error;
      }
    }
    if (auto error = checkFinite(field + ".radius", c.radius); !error.empty()) return error;
    const std::string radius = field + ".radius";
    return checkRange(radius.c_str(), c.radius, 0, kMaxLength);
  }
  if (auto error = checkRectangles(problem.rectangles); !error.empty()) return error;
  if (auto error = checkRobotSize(problem); !error.empty()) return error;
  if (auto error = checkPointFinite("start", problem.start); !error.empty()) return error;
  if (auto error = checkPointFinite("goal", problem.goal); !error.empty()) return error;
  if (auto error = checkPlaceable("start", problem.start, problem); !error.empty()) return error;
  return checkPlaceable("goal", problem.goal, problem);
}

std::string validateOptions(const PlannerOptions& o, int max_iterations_cap) {
  if (auto error = checkFinite("step", o.step); !error.empty()) return error;
  if (auto error = checkRange("step", o.step, kMinStep, kMaxLength); !error.empty()) return error;
  if (auto error = checkFinite("goal_bias", o.goal_bias); !error.empty()) return error;
  if (o.goal_bias < 0 || o.goal_bias > 1) {
    return "goal_bias: must be in [0, 1] (got " + show(o.goal_bias) + ")";
  }
  if (o.max_iterations < 1) {
    return "max_iterations: must be >= 1 (got " + std::to_string(o.max_iterations) + ")";
  }
  if (o.max_iterations > max_iterations_cap) {
    return "max_iterations: " + std::to_string(o.max_iterations) + " is above the cap of " +
           std::to_string(max_iterations_cap);
  }
  if (auto error = checkFinite("goal_tolerance", o.goal_tolerance); !error.empty()) return error;
  if (auto error = checkRange("goal_tolerance", o.goal_tolerance, 0, kMaxLength); !error.empty()) {
    return error;
  }
  if (auto error = checkFinite("max_planning_time", o.max_planning_time); !error.empty()) {
    return error;
  }
  if (auto error = checkRange("max_planning_time", o.max_planning_time, 0, kMaxPlanningTime, "s");
      !error.empty()) {
    return error;
  }
  if (o.max_rejection_tries < 1) return "max_rejection_tries: must be >= 1";
  if (o.smoothing_tries < 0) return "smoothing_tries: must be >= 0";
  return "";
}

}  // namespace

std::string validate(const Problem& problem, const PlannerOptions& options,
                     int max_iterations_cap) {
  if (auto error = validateProblem(problem); !error.empty()) return error;
  return validateOptions(options, max_iterations_cap);
}

}  // namespace roomba_rrt::planning
