// Parallel (BehaviorTree.CPP): tick every child on every tick until enough succeed or fail.
#pragma once

#include <cstddef>
#include <vector>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// A number of children as the Parallel nodes' ports give it: `count`, or counted from the
/// number of children when negative (-1: all of them, -2: all but one).
long childThreshold(int count, std::size_t children);
/// "" when childThreshold(count, children) is 1..children, else what is wrong, naming `port`.
std::string childThresholdProblem(const char* port, int count, std::size_t children);

/// Ticks, from left to right in one tick, every child that has not finished in this run (a
/// child that finished is not ticked again until Parallel starts anew). `success_count` and
/// `failure_count` are thresholds; a negative one counts from the number of children N
/// (-1: all N, -2: N - 1, ...).
///
/// After each child's tick, when the children that returned
/// - SUCCESS reach `success_count`: the running children are halted, Parallel returns SUCCESS.
/// - FAILURE reach `failure_count`, or leave too few to reach `success_count`: the running
///   children are halted, Parallel returns FAILURE.
/// Otherwise (children still RUNNING) it returns RUNNING after ticking them all. A SKIPPED child
/// counts as a success when `success_count` is negative (so children all skipped reach "all");
/// otherwise, when every child was skipped in one tick, Parallel returns SKIPPED.
class ParallelNode final : public ControlNode {
 public:
  static PortList providedPorts() {
    return {inputPort<int>("success_count", "successes needed (-1: every child)", "-1"),
            inputPort<int>("failure_count", "failures that fail it (-1: every child)", "1")};
  }
  ParallelNode(std::string name, int success_count, int failure_count);

  /// Both thresholds must come to 1..N with N children.
  std::string childCountProblem(std::size_t children) const override;

 private:
  void onEnter() override;
  Status onTick() override;

  int success_count_;
  int failure_count_;
  std::vector<bool> finished_;  ///< per child: it finished in this run
  long successes_ = 0;
  long failures_ = 0;
};

}  // namespace roomba_rrt::bt
