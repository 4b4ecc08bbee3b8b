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

#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::navigation {

/// What a navigation plan must avoid: the room, its furniture and the robot's size. The planner
/// keeps the robot's disc (radius + clearance) clear of every wall and obstacle, with the
/// planning library's exact tests (circles grown, rectangles rounded by the margin).
/// A start inside a grown obstacle (a robot hugging furniture) is planned from the nearest free
/// point within 0.25 m, the path starting with the real start.
struct NavWorld {
  planning::Bounds bounds;                ///< the room (walls)
  std::vector<planning::Circle> circles;  ///< round obstacles
  std::vector<planning::Rectangle> rectangles;
  double robot_radius = 0;  ///< m, 0: a point
  double clearance = 0.05;  ///< m, kept on top of the radius
};

/// The simulator's world as a planning world (room, furniture, robot radius).
NavWorld navWorldFrom(const world::World& world, double clearance = 0.05);

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
  /// Whether the part of `path` from point `from` on is free for the robot (a replan is due
  /// when it is not); the default says yes. A first point that is not free (the robot's own
  /// start, a little inside the clearance) does not count.
  virtual bool isPathFree(const Path& path, std::size_t from) const {
    (void)path;
    (void)from;
    return true;
  }
};

/// The planning library in-process: plan() on a worker thread (kThread), or, for deterministic
/// simulations in one loop, inside request() with the result reported by the next poll()
/// (kInline). Each request uses seed options.seed + (number of earlier requests).
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

  /// std::invalid_argument naming the field when the world or options are invalid. With
  /// `plan_function`, requests are planned by it (the world still answers isPathFree and
  /// freeStart).
  InProcessPlanner(NavWorld world, const planning::PlannerOptions& options,
                   Mode mode = Mode::kThread, PlanFunction plan_function = {});
  ~InProcessPlanner() override;

  void request(const planning::Point2& start, const planning::Point2& goal) override;
  bool poll(PlanReply& reply) override;
  void cancel() override;
  bool isPathFree(const Path& path, std::size_t from) const override;

  /// Plans at once on the calling thread (also what the worker runs).
  PlanReply planNow(const planning::Point2& start, const planning::Point2& goal,
                    std::uint32_t seed) const;
  const NavWorld& world() const { return world_; }
  /// Whether the robot's centre may be at `p` (inside the shrunk bounds, outside every grown
  /// obstacle).
  bool isPointFree(const planning::Point2& p) const;
  /// `start` if it is free, else the nearest free point within 0.25 m of it (`start` when none
  /// is): where a plan for a robot hugging furniture starts.
  planning::Point2 freeStart(const planning::Point2& start) const;

 private:
  void work();

  NavWorld world_;
  planning::PlannerOptions options_;
  Mode mode_;
  PlanFunction plan_function_;
  planning::Problem base_;              ///< the world as a planning problem (start, goal unset)
  planning::CollisionChecker checker_;  ///< exact tests against the grown obstacles
  planning::Bounds shrunk_;             ///< bounds shrunk by radius + clearance

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
