// Sleep (BehaviorTree.CPP's action): return RUNNING for a while, then SUCCESS.
#pragma once

#include <cstdint>
#include <limits>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/ports.h"
#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// Returns RUNNING until `ticks` ticks of the tree's clock (Blackboard::tick(): no wall clock)
/// have passed since the tick it was entered in, then SUCCESS (0 ticks: SUCCESS at once).
/// `msec` (BehaviorTree.CPP's port) becomes ticks at the tree's tick rate. A halt, or a
/// finished run, starts the wait anew on the next tick.
class SleepNode final : public LeafNode {
 public:
  static PortList providedPorts() {
    constexpr double kMax = static_cast<double>(std::numeric_limits<long>::max());
    return {inputPort<long>("msec", "milliseconds to wait").range(0, kMax)};
  }
  /// `ticks` >= 0 (util::InvalidInput otherwise); `clock` (the tree's blackboard) must outlive
  /// the node.
  SleepNode(std::string name, long ticks, const Blackboard& clock);

 private:
  void onEnter() override { start_ = clock_.tick(); }
  Status onTick() override {
    return clock_.tick() - start_ >= ticks_ ? Status::kSuccess : Status::kRunning;
  }

  const Blackboard& clock_;
  std::uint64_t ticks_;
  std::uint64_t start_ = 0;  ///< the tick it was entered in
};

}  // namespace roomba_rrt::bt
