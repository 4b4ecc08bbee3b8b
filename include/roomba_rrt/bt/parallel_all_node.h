// ParallelAll (BehaviorTree.CPP): tick every child until all have finished, then count failures.
#pragma once

#include <cstddef>
#include <vector>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/parallel_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Ticks, from left to right in one tick, every child that has not finished in this run (a
/// finished child is not ticked again until ParallelAll starts anew), and never stops a child
/// early.
///
/// - While a child is RUNNING: returns RUNNING.
/// - SKIPPED children count as finished, without failing; when every child was skipped in one
///   tick, ParallelAll returns SKIPPED.
/// - When every child has finished (SUCCESS or FAILURE): returns FAILURE if at least
///   `max_failures` of them failed (a negative value counts from the number of children N: -1 is
///   all N), else SUCCESS.
class ParallelAllNode final : public ControlNode {
 public:
  static PortList providedPorts() {
    return {inputPort<int>("max_failures", "failures that fail it (-1: every child)", "1")};
  }
  ParallelAllNode(std::string name, int max_failures);

  /// `max_failures` must come to 1..N with N children.
  std::string childCountProblem(std::size_t children) const override;

 private:
  void onEnter() override;
  Status onTick() override;

  int max_failures_;
  std::vector<bool> finished_;  ///< per child: it finished in this run
  std::size_t done_ = 0;
  long failures_ = 0;
};

}  // namespace roomba_rrt::bt
