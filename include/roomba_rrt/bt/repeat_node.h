// Repeat: run its child a number of times, as long as it succeeds.
#pragma once

#include <limits>

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Runs the child `num_cycles` times (−1: forever). Each repetition starts on the tick after the
/// previous one succeeded, so a child that succeeds at once cannot spin inside one tick.
///
/// When the child returns
/// - SUCCESS: one cycle is done; after `num_cycles` cycles Repeat returns SUCCESS, otherwise it
///   returns RUNNING and enters the child anew on the next tick.
/// - FAILURE: Repeat returns FAILURE (the cycle count starts over on the next run).
/// - RUNNING: Repeat returns RUNNING.
/// - SKIPPED: returns SKIPPED (the child did not run, so neither does it).
class RepeatNode final : public DecoratorNode {
 public:
  /// `num_cycles` (int, required): repetitions, or -1 for forever.
  static PortList providedPorts() {
    return {inputPort<int>("num_cycles", "repetitions, or -1 for forever")
                .range(-1, std::numeric_limits<int>::max())};
  }
  /// `num_cycles` ≥ 1, or −1 for forever (util::InvalidInput naming it otherwise).
  RepeatNode(std::string name, int num_cycles);

 private:
  void onEnter() override { done_ = 0; }
  Status onTick() override;

  int num_cycles_;
  int done_ = 0;  ///< cycles completed in this run
};

}  // namespace roomba_rrt::bt
