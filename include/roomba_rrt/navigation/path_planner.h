// The planner interface of the navigation leaves (ComputePath): start and goal in, a path out,
// computed off the tick thread. In-process it is the planning library (rrt_planning); in the
// node it can be the ~plan_path service behind the same interface.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "roomba_rrt/navigation/path_checker.h"
#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::navigation {

/// A finished plan.
struct PlanReply {
  bool success = false;
  std::string message;  ///< why not (names the field: "goal: inside obstacle 3", ...)
  Path path;            ///< start … goal (the goal exactly), empty on failure
  double planning_ms = 0;
};

/// Makes a planned path start with the robot's own `start` (a plan from freeStart() begins
/// elsewhere) and end exactly at `goal`.
void finishPath(const planning::Point2& start, const planning::Point2& goal, Path& path);

/// Plans asynchronously: request() returns at once, poll() reports the result when it is ready.
/// One caller thread (the tree's); implementations plan elsewhere.
class PathPlanner {
 public:
  virtual ~PathPlanner() = default;
  /// Starts a plan; a plan still pending is abandoned (its result is never reported).
  virtual void request(const planning::Point2& start, const planning::Point2& goal) = 0;
  /// True once the last requested plan is done: its result is swapped into `reply` (the
  /// reply's old vectors are recycled, so steady replanning does not allocate on this thread).
  virtual bool poll(PlanReply& reply) = 0;
  /// Abandons the pending plan, if any.
  virtual void cancel() = 0;
};

/// The planning library in-process: plan() on a worker thread (kThread), or, for deterministic
/// simulations in one loop, inside request() with the result reported by the next poll()
/// (kInline). Each request uses seed options.seed + (number of earlier requests).
///
/// The world is a planning::Problem whose start and goal are ignored: the planner keeps the
/// robot's disc (robot_radius + clearance) clear of every wall and obstacle, with the planning
/// library's exact tests (circles grown, rectangles rounded by the margin). A start inside a grown
/// obstacle (a robot hugging furniture) is planned from the nearest free point within 0.25 m
/// (PathChecker::freeStart), the path starting with the real start.
///
/// kThread on the tick thread: poll() is one atomic load (and a swap of vectors when a result
/// is ready, so the finished path's memory is freed by the worker, not the tick); request(), once
/// per plan, takes the worker's mutex, which the worker holds only to pick up a job or publish a
/// result, never while planning.
class InProcessPlanner final : public PathPlanner {
 public:
  enum class Mode { kThread, kInline };
  /// What plans a request (start already moved to a free point, seed), in place of the
  /// library: the roomba_bt node's client of the ~plan_path service. Runs on the worker thread
  /// in kThread; the reply's path is finished with finishPath().
  using PlanFunction = std::function<PlanReply(const planning::Point2& start,
                                               const planning::Point2& goal, std::uint32_t seed)>;

  /// util::InvalidInput naming the field when the world or options are invalid. With
  /// `plan_function`, requests are planned by it (the world still moves the start to a free
  /// point).
  InProcessPlanner(planning::Problem world, const planning::PlannerOptions& options,
                   Mode mode = Mode::kThread, PlanFunction plan_function = {});
  ~InProcessPlanner() override;
  /// What the constructor refuses (util::InvalidInput naming the field, source "planner").
  static void validate(const planning::Problem& world, const planning::PlannerOptions& options);

  void request(const planning::Point2& start, const planning::Point2& goal) override;
  bool poll(PlanReply& reply) override;
  void cancel() override;

  /// Plans at once on the calling thread (also what the worker runs).
  PlanReply planNow(const planning::Point2& start, const planning::Point2& goal,
                    std::uint32_t seed) const;
  const planning::Problem& world() const { return checker_.world(); }

 private:
  void work();

  PathChecker checker_;  ///< the world; where a plan may start
  planning::PlannerOptions options_;
  Mode mode_;
  PlanFunction plan_function_;

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::uint64_t requested_ = 0;  ///< generation of the last request (guarded by mutex_)
  planning::Point2 start_, goal_;
  std::atomic<std::uint64_t> done_{0};  ///< generation whose result_ is ready
  std::atomic<std::uint64_t> wanted_{0};
  PlanReply result_;
  std::uint32_t requests_ = 0;
  std::thread worker_;
};

}  // namespace roomba_rrt::navigation
