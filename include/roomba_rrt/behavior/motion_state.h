// An FSM state that runs one of the Roomba's motion primitives.
#pragma once

#include "roomba_rrt/behavior/motion_primitives.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/fsm/state.h"

namespace roomba_rrt::behavior {

/// The lab's FSM state around a motion primitive (MoveForward, MoveInSpiral, GoBack, Rotate):
///
/// - enter(): the motion starts (Rotate draws its angle here);
/// - checkTransition(): a bump goes to `on_bump`, the end of the motion's time to `on_time_up`
///   (the bumper is checked first; GoBack and Rotate ignore it);
/// - execute(): writes the motion's command for this tick into the context.
template <class Motion>
class MotionState final : public fsm::State {
 public:
  MotionState(RoombaState id, Motion motion, RoombaContext& context, fsm::StateId on_bump,
              fsm::StateId on_time_up)
      : fsm::State(toString(id)),
        id_(id),
        motion_(std::move(motion)),
        context_(context),
        on_bump_(on_bump),
        on_time_up_(on_time_up) {}

  void enter() override { motion_.enter(context_); }

  fsm::StateId checkTransition() override {
    switch (motion_->check(context_.bumper)) {
      case MotionEvent::kBumped:
        return on_bump_;
      case MotionEvent::kTimeUp:
        return on_time_up_;
      case MotionEvent::kNone:
        break;
    }
    return fsm::kStay;
  }

  void execute() override {
    context_.cmd = motion_->execute();
    context_.state = id_;
    context_.state_name = &name();
  }

 private:
  RoombaState id_;
  MotionHolder<Motion> motion_;
  RoombaContext& context_;
  fsm::StateId on_bump_;
  fsm::StateId on_time_up_;
};

}  // namespace roomba_rrt::behavior
