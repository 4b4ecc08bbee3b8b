// Retry: run its child again after a failure, up to a number of attempts.
#pragma once

#include <limits>

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Gives the child up to `num_attempts` attempts (−1: unlimited). Each new attempt starts on the
/// tick after the failed one, so a child that fails at once cannot spin inside one tick.
///
/// When the child returns
/// - SUCCESS: Retry returns SUCCESS (the attempt count starts over on the next run).
/// - FAILURE: one attempt is used up; after `num_attempts` failures Retry returns FAILURE,
///   otherwise it returns RUNNING and enters the child anew on the next tick.
/// - RUNNING: Retry returns RUNNING.
/// - SKIPPED: returns SKIPPED (the child did not run, so neither does it).
class RetryNode final : public DecoratorNode {
 public:
  /// `num_attempts` (int, required): attempts, or -1 for unlimited.
  static PortList providedPorts() {
    return {inputPort<int>("num_attempts", "attempts, or -1 for unlimited")
                .range(-1, std::numeric_limits<int>::max())};
  }
  /// `num_attempts` ≥ 1, or −1 for unlimited (util::InvalidInput naming it otherwise).
  RetryNode(std::string name, int num_attempts);

 private:
  void onEnter() override { failed_ = 0; }
  Status onTick() override;

  int num_attempts_;
  int failed_ = 0;  ///< attempts failed in this run
};

}  // namespace roomba_rrt::bt
