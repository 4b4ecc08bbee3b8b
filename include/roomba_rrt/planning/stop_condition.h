// When a plan must stop before its iterations are used up: a wall-clock budget, or a caller's
// request (a node shutting down). The planners' counterpart of OMPL's PlannerTerminationCondition.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace roomba_rrt::planning {

/// The planners call it once per loop (RRT-Connect's connect steps included; plain RRT, whose
/// loops are the shortest, every 16th loop). It reads the clock and asks `requested` only every
/// `stride` calls: the stride starts at 1, doubles while the time between two readings stays
/// below about a millisecond and halves when it exceeds two, between 1 and 1024. A cheap loop
/// (the lab's, about 80 ns) thus pays a decrement, and one clock reading per thousands of loops;
/// an expensive one (RRT* on a large tree) is stopped within a few loops of the limit. One loop
/// itself (e.g. a free-space sample of up to max_rejection_tries draws) is never interrupted.
/// Without a limit and a request it never reads the clock.
class StopCondition {
 public:
  /// Never stops.
  StopCondition() = default;
  /// Stops once `max_seconds` (> 0; 0 means no limit) have passed since construction, or once
  /// `requested()` returns true (empty: never).
  explicit StopCondition(double max_seconds, std::function<bool()> requested = {});

  /// Counts one loop; true when the plan must stop (and from then on).
  bool operator()() {
    if (--countdown_ > 0) return false;
    return check();
  }
  /// Why it stopped: "max_planning_time: ..." or "stopped on request"; "" while it has not.
  const std::string& reason() const { return reason_; }

 private:
  using Clock = std::chrono::steady_clock;
  bool check();

  std::int64_t countdown_ = INT64_MAX;  ///< calls until the next check
  std::int64_t stride_ = 1;
  double max_seconds_ = 0;
  std::function<bool()> requested_;
  Clock::time_point started_{}, deadline_{}, last_check_{};
  std::string reason_;
};

}  // namespace roomba_rrt::planning
