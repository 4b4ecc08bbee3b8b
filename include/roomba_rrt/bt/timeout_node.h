// Timeout: give its child a fixed number of ticks (or milliseconds at the tick rate) to finish.
#pragma once

#include <limits>

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Lets the child run for at most `ticks` ticks (time is counted in ticks, so a tree is
/// deterministic and needs no clock; at 60 Hz, 60 ticks are one second).
///
/// When the child returns
/// - SUCCESS: Timeout returns SUCCESS.
/// - FAILURE: Timeout returns FAILURE.
/// - RUNNING: Timeout returns RUNNING, unless this was the child's `ticks`-th tick in this run:
///   then the child is halted and Timeout returns FAILURE.
/// - SKIPPED: returns SKIPPED (the child did not run, so neither does it).
class TimeoutNode final : public DecoratorNode {
 public:
  /// Exactly one of `msec` (BehaviorTree.CPP v4's port: milliseconds, turned into ticks at the
  /// tree's tick rate) and `ticks` (ticks the child may run); the other stays 0.
  static PortList providedPorts() {
    constexpr double kMax = static_cast<double>(std::numeric_limits<long>::max());
    return {
        inputPort<long>("msec", "milliseconds the child may run (at the tick rate)", "0")
            .range(0, kMax),
        inputPort<long>("ticks", "ticks the child may run (instead of msec)", "0").range(0, kMax)};
  }
  /// `ticks` ≥ 1 (util::InvalidInput naming it otherwise).
  TimeoutNode(std::string name, long ticks);

  /// The ticks in `msec` milliseconds at `tick_rate` Hz, rounded to the nearest tick, at least
  /// one (and at most the largest long).
  static long ticksFor(long msec, double tick_rate);

 private:
  void onEnter() override { elapsed_ = 0; }
  Status onTick() override;

  long ticks_;
  long elapsed_ = 0;  ///< child ticks in this run
};

}  // namespace roomba_rrt::bt
