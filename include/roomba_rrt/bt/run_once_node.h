// RunOnce (BehaviorTree.CPP): run the child to its end once, then never again.
#pragma once

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Until the child has finished once, RunOnce ticks it and returns its status (a halt before it
/// finished does not count). When it has, RunOnce does not tick it again for the life of the
/// tree and returns SKIPPED (`then_skip`, the default) or the status the child finished with.
class RunOnceNode final : public DecoratorNode {
 public:
  static PortList providedPorts() {
    return {
        inputPort<bool>("then_skip", "after the first run: SKIPPED, or the same status", "true")};
  }
  RunOnceNode(std::string name, bool then_skip)
      : DecoratorNode(std::move(name)), then_skip_(then_skip) {}

 private:
  Status onTick() override;

  bool then_skip_;
  bool done_ = false;
  Status result_ = Status::kSuccess;  ///< what the child finished with
};

}  // namespace roomba_rrt::bt
