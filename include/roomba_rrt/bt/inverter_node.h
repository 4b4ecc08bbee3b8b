// Inverter: swap its child's SUCCESS and FAILURE.
#pragma once

#include "roomba_rrt/bt/decorator_node.h"

namespace roomba_rrt::bt {

/// When the child returns
/// - SUCCESS: the Inverter returns FAILURE.
/// - FAILURE: the Inverter returns SUCCESS.
/// - RUNNING: the Inverter returns RUNNING.
/// - SKIPPED: returns SKIPPED (the child did not run, so neither does it).
class InverterNode final : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;

 private:
  Status onTick() override;
};

}  // namespace roomba_rrt::bt
