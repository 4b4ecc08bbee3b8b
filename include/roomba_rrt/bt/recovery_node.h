// RecoveryNode (Nav2): run an action; when it fails, run a recovery and try the action again.
#pragma once

#include <limits>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Exactly two children: the action (first) and its recovery (second). Up to
/// `number_of_retries` recoveries per run; each new try of the action starts on the tick after
/// the recovery succeeded, so nothing can spin inside one tick.
///
/// When the action returns
/// - SUCCESS: RecoveryNode returns SUCCESS (the recovery count starts over on the next run).
/// - FAILURE: if recoveries remain, the recovery is entered and ticked in the same tick;
///   otherwise RecoveryNode returns FAILURE.
/// - RUNNING: RecoveryNode returns RUNNING.
///
/// When the recovery returns
/// - SUCCESS: one recovery is used up; RecoveryNode returns RUNNING and enters the action anew
///   on the next tick.
/// - FAILURE: RecoveryNode returns FAILURE (the recovery could not help).
/// - RUNNING: RecoveryNode returns RUNNING and ticks the recovery on the next tick.
///
/// A skipped action or recovery makes RecoveryNode return SKIPPED (nothing ran to recover from,
/// or nothing recovered).
class RecoveryNode final : public ControlNode {
 public:
  /// `number_of_retries` (int, default 1): recoveries per run, in [0, 2^31 - 1].
  static PortList providedPorts() {
    return {inputPort<int>("number_of_retries", "recoveries before giving up", "1")
                .range(0, std::numeric_limits<int>::max())};
  }
  /// `number_of_retries` >= 0 (util::InvalidInput naming it otherwise).
  RecoveryNode(std::string name, int number_of_retries);

  std::size_t requiredChildren() const override { return 2; }
  /// Recoveries that succeeded in this run.
  int retries() const { return retries_; }

 private:
  void onEnter() override {
    retries_ = 0;
    recovering_ = false;
  }
  Status onTick() override;

  int number_of_retries_;
  int retries_ = 0;
  bool recovering_ = false;  ///< the recovery (second child) is the current child
};

}  // namespace roomba_rrt::bt
