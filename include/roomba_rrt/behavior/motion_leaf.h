// A BT leaf that runs one of the Roomba's motion primitives.
#pragma once

#include "roomba_rrt/behavior/motion_primitives.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::behavior {

/// The lab's BT leaf around a motion primitive (MoveForward, MoveInSpiral, GoBack, Rotate):
///
/// - enter (first tick after a (re)start): the motion starts (Rotate draws its angle here);
/// - execute: a bump → FAILURE (MoveForward and MoveInSpiral; GoBack and Rotate ignore the
///   bumper); the motion's time is up → SUCCESS; otherwise the motion's command for this tick
///   goes into the context → RUNNING. A leaf that finishes writes no command.
template <class Motion>
class MotionLeaf final : public bt::LeafNode {
 public:
  MotionLeaf(std::string name, RoombaState id, Motion motion, RoombaContext& context)
      : bt::LeafNode(std::move(name)), id_(id), motion_(std::move(motion)), context_(context) {}

 private:
  void onEnter() override { motion_.enter(context_); }

  bt::Status onTick() override {
    switch (motion_->check(context_.bumper)) {
      case MotionEvent::kBumped:
        return bt::Status::kFailure;
      case MotionEvent::kTimeUp:
        return bt::Status::kSuccess;
      case MotionEvent::kNone:
        break;
    }
    context_.cmd = motion_->execute();
    context_.state = id_;
    context_.state_name = &name();
    return bt::Status::kRunning;
  }

  RoombaState id_;
  MotionHolder<Motion> motion_;
  RoombaContext& context_;
};

}  // namespace roomba_rrt::behavior
