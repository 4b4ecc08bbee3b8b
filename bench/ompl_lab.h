// What the OMPL comparisons share (bench/ompl_comparison.cpp: the lab's scenarios and the
// furnished room; bench/map_comparison.cpp: the shared maps): CPU-time measurement, OMPL set up
// with the planning library's own CollisionChecker, our plan() timed the same way, the
// statistics and the output's numbers.
#pragma once

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/Goal.h>
#include <ompl/base/MotionValidator.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/config.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/planner.h"

namespace roomba_rrt::bench {

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace rp = roomba_rrt::planning;

// Debian's OMPL leaves OMPL_VERSION empty; the numeric parts are right.
inline const std::string kOmplVersion = std::to_string(OMPL_MAJOR_VERSION) + "." +
                                        std::to_string(OMPL_MINOR_VERSION) + "." +
                                        std::to_string(OMPL_PATCH_VERSION);

/// CPU time of the calling thread. Solves are timed with it rather than with the wall clock: on
/// a shared machine the wall clock also counts the time other processes held the core, which
/// would make both sides look slower by a varying amount. On an idle machine the two agree.
inline double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// What a timing costs by itself: the smallest CPU time between two consecutive readings of the
/// thread's clock, out of 1000 (a system call on some VMs: about 3 µs on the benchmark machine,
/// a quarter of a room solve). Set once in main() and subtracted from every solve of both sides.
inline double clockOverhead() {
  double least = 1;
  for (int i = 0; i < 1000; ++i) {
    const double t0 = threadCpuSeconds();
    least = std::min(least, threadCpuSeconds() - t0);
  }
  return least;
}
inline double g_clock_overhead = 0;

/// CPU seconds since the reading `t0`, without the readings' own cost.
inline double cpuSecondsSince(double t0) {
  return std::max(0.0, threadCpuSeconds() - t0 - g_clock_overhead);
}

// ---------------------------------------------------------------------------------------------
// OMPL's side: stock geometric::RRT on a 2-D RealVectorStateSpace.

inline rp::Point2 point(const ob::State* s) {
  const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
  return {v[0], v[1]};
}

/// The lab's motion check for OMPL, by the planning library's own CollisionChecker: only the
/// end state (points) or the exact segment-circle test (segments); zero-length steps fail.
class LabMotionValidator : public ob::MotionValidator {
 public:
  LabMotionValidator(const ob::SpaceInformationPtr& si, const rp::CollisionChecker& checker)
      : ob::MotionValidator(si), checker_(checker) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const rp::Point2 a = point(s1), b = point(s2);
    // As in the library's extendTree(): a step of length zero (the target is already a tree
    // node) adds nothing. Without this, OMPL re-inserts the goal once per goal-biased sample
    // when the goal is never accepted, and its GNAT index degrades on the duplicates.
    const bool ok = (a.x != b.x || a.y != b.y) && checker_.isMotionFree(a, b);
    ok ? ++valid_ : ++invalid_;
    return ok;
  }

  // Only called by planners that extend greedily (not by RRT); reports the start as last valid.
  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& last_valid) const override {
    const bool ok = checkMotion(s1, s2);
    if (!ok) {
      if (last_valid.first != nullptr) si_->copyState(last_valid.first, s1);
      last_valid.second = 0.0;
    }
    return ok;
  }

 private:
  const rp::CollisionChecker& checker_;
};

/// The goal with the library's goal_tolerance 0 ("never stops early"): never satisfied, but
/// still sampled by the goal bias, so the tree keeps growing towards it for all iterations.
class NeverReachedGoal : public ob::GoalState {
 public:
  using ob::GoalState::GoalState;
  bool isSatisfied(const ob::State* st, double* distance) const override {
    if (distance != nullptr) *distance = distanceGoal(st);
    return false;
  }
};

struct Solve {
  bool solved = false;
  double length = 0;   // path length when solved
  double seconds = 0;  // CPU time of the solve call only
  long work = 0;       // OMPL: motion checks made; ours: iterations (what is shared is the checker)
};

/// How OMPL checks a motion: with the library's exact checker (the same sweep our planner calls),
/// or as a user sets it up: OMPL's DiscreteMotionValidator, the exact point check every
/// `resolution` metres along the motion (../shared/PERFORMANCE.md: a quarter cell on a map).
struct MotionCheck {
  double resolution = 0;  ///< m between the points checked; 0: the library's exact sweep
};

/// An OMPL planner (RRT by default; RRTConnect, RRTstar for the room rows) set up once for one
/// problem; solve() runs a fresh tree each call. A robot with a size (problem.robot_radius +
/// clearance) gets the grown world exactly as the library plans in it: the library's checker of
/// the grown obstacles and the bounds shrunk by the margin.
template <typename Planner = og::RRT>
class OmplLab {
 public:
  OmplLab(const rp::Problem& problem, const rp::PlannerOptions& options, MotionCheck motion = {})
      : bounds_(rp::shrink(problem.bounds, rp::robotMargin(problem))),
        checker_(rp::collisionChecker(problem, options.collision)) {
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, bounds_.x_min);
    bounds.setHigh(0, bounds_.x_max);
    bounds.setLow(1, bounds_.y_min);
    bounds.setHigh(1, bounds_.y_max);
    space->setBounds(bounds);

    si_ = std::make_shared<ob::SpaceInformation>(space);
    si_->setStateValidityChecker([this](const ob::State* s) {
      const rp::Point2 p = point(s);
      return rp::contains(bounds_, p) && checker_.isFree(p);
    });
    if (motion.resolution > 0) {
      // OMPL's resolution is a fraction of the space's extent (the bounds' diagonal).
      si_->setStateValidityCheckingResolution(motion.resolution / space->getMaximumExtent());
      si_->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si_));
    } else {
      si_->setMotionValidator(std::make_shared<LabMotionValidator>(si_, checker_));
    }
    si_->setup();

    ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space);
    start[0] = problem.start.x;
    start[1] = problem.start.y;
    goal[0] = problem.goal.x;
    goal[1] = problem.goal.y;
    pdef_ = std::make_shared<ob::ProblemDefinition>(si_);
    pdef_->addStartState(start);
    auto goal_state = options.goal_tolerance > 0 ? std::make_shared<ob::GoalState>(si_)
                                                 : std::make_shared<NeverReachedGoal>(si_);
    goal_state->setState(goal);
    goal_state->setThreshold(options.goal_tolerance);
    pdef_->setGoal(goal_state);

    planner_ = std::make_shared<Planner>(si_);
    planner_->setRange(options.step);
    if constexpr (!std::is_same_v<Planner, og::RRTConnect>) {
      planner_->setGoalBias(options.goal_bias);  // RRTConnect has none: the goal tree pulls
    }
    planner_->setProblemDefinition(pdef_);
    planner_->setup();
  }

  /// At most `iterations` iterations (stops at the first solution, except RRTstar).
  Solve solve(unsigned iterations) {
    return solveUntil(
        [iterations](double) { return ob::IterationTerminationCondition(iterations); });
  }
  /// Until the solving thread has used `seconds` of CPU time (RRTstar keeps improving until then;
  /// CPU time, as our side is measured, so load on the machine does not shorten the budget).
  Solve solveFor(double seconds) {
    return solveUntil([seconds](double t0) {
      const double deadline = t0 + seconds;
      return ob::PlannerTerminationCondition([deadline] { return threadCpuSeconds() >= deadline; });
    });
  }

 private:
  /// Clears the previous run (not timed), then solves until make_stop(start time) says so.
  template <typename MakeStop>
  Solve solveUntil(const MakeStop& make_stop) {
    planner_->clear();
    pdef_->clearSolutionPaths();
    const ob::MotionValidatorPtr& motions = si_->getMotionValidator();
    motions->resetMotionCounter();
    const double t0 = threadCpuSeconds();
    const ob::PlannerStatus status = planner_->solve(make_stop(t0));
    Solve out;
    out.seconds = cpuSecondsSince(t0);
    out.work = static_cast<long>(motions->getValidMotionCount() + motions->getInvalidMotionCount());
    out.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
    if (out.solved) out.length = pdef_->getSolutionPath()->length();
    return out;
  }

  rp::Bounds bounds_;
  rp::CollisionChecker checker_;
  ob::SpaceInformationPtr si_;
  ob::ProblemDefinitionPtr pdef_;
  std::shared_ptr<Planner> planner_;
};
using OmplLabRrt = OmplLab<og::RRT>;

// ---------------------------------------------------------------------------------------------
// Our side: rrt_planning's plan(), timed the same way.

inline Solve solveOurs(const rp::Problem& problem, rp::PlannerOptions options, unsigned iterations,
                       std::uint32_t seed) {
  options.max_iterations = static_cast<int>(iterations);
  options.seed = seed;
  const double t0 = threadCpuSeconds();
  const rp::PlanResult result = rp::plan(problem, options);
  Solve out;
  out.seconds = cpuSecondsSince(t0);
  out.solved = result.success;
  out.work = result.iterations;
  if (out.solved) out.length = result.length;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Statistics and the experiment.

inline double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  if (v.size() % 2 == 1) return v[mid];
  return 0.5 * (v[mid] + *std::max_element(v.begin(), v.begin() + mid));
}

struct Summary {
  double solved_percent = 0;
  double mean_length = std::nan("");  // over solved runs
  double median_seconds = 0;
};

/// Runs `solve(i)` for i < warmup untimed, then `runs` times, and summarises.
inline Summary measure(int warmup, int runs, const std::function<Solve(int)>& solve) {
  for (int i = 0; i < warmup; ++i) solve(i);
  std::vector<double> seconds;
  double length_sum = 0;
  int solved = 0;
  for (int i = 0; i < runs; ++i) {
    const Solve s = solve(warmup + i);
    seconds.push_back(s.seconds);
    if (s.solved) {
      ++solved;
      length_sum += s.length;
    }
  }
  Summary out;
  out.solved_percent = runs > 0 ? 100.0 * solved / runs : 0;
  if (solved > 0) out.mean_length = length_sum / solved;
  out.median_seconds = median(seconds);
  return out;
}

/// A number for the JSON and Markdown output: fixed `precision` decimals, "null" if not finite.
inline std::string num(double v, int precision) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(precision);
  s << v;
  return s.str();
}

/// The most iterations of our planner (`options`, RRT* in practice) on `query` whose solve stays
/// within `budget` seconds of CPU time (doubling, then the last count that fit): our planner
/// stops by iterations, OMPL's by time.
inline unsigned iterationsWithin(const rp::Problem& query, const rp::PlannerOptions& options,
                                 double budget) {
  const auto within = [&](unsigned n) {
    return solveOurs(query, options, n, 1u).seconds <= budget;
  };
  unsigned fits = 50, over = 100;
  while (over < 5000000 && within(over)) {
    fits = over;
    over *= 2;
  }
  for (int step = 0; step < 4 && over - fits > 1; ++step) {  // bisect to within 1/16
    const unsigned mid = fits + (over - fits) / 2;
    (within(mid) ? fits : over) = mid;
  }
  return fits - fits / 16;  // a margin for the other seeds' spread
}

}  // namespace roomba_rrt::bench
