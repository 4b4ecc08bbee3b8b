// Delay (BehaviorTree.CPP): wait a while after being entered, then run the child.
#pragma once

#include <cstdint>
#include <limits>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Waits `ticks` ticks of the tree's clock (Blackboard::tick(), as RateController: no wall
/// clock, so a tree stays deterministic) from the tick it is entered in, then runs its child.
/// `delay_msec` (BehaviorTree.CPP's port) becomes ticks at the tree's tick rate.
///
/// While waiting it returns RUNNING without ticking the child; the child is first ticked `ticks`
/// ticks after Delay was entered (0: in the same tick). Then, when the child returns
/// - SUCCESS: returns SUCCESS; the next tick enters Delay anew and waits again.
/// - FAILURE: returns FAILURE; likewise.
/// - RUNNING: returns RUNNING and ticks the child on the next tick (no further wait).
/// - SKIPPED: returns SKIPPED (the child did not run, so neither does it).
///
/// Halting it halts the child; the next tick waits again.
class DelayNode final : public DecoratorNode {
 public:
  static PortList providedPorts() {
    constexpr double kMax = static_cast<double>(std::numeric_limits<long>::max());
    return {
        inputPort<long>("delay_msec", "milliseconds before the child is ticked").range(0, kMax)};
  }
  /// `ticks` >= 0 (util::InvalidInput otherwise); `clock` (the tree's blackboard) must outlive
  /// the node.
  DelayNode(std::string name, long ticks, const Blackboard& clock);

 private:
  void onEnter() override { start_ = clock_.tick(); }
  Status onTick() override;

  const Blackboard& clock_;
  std::uint64_t ticks_;
  std::uint64_t start_ = 0;  ///< the tick it was entered in
};

}  // namespace roomba_rrt::bt
