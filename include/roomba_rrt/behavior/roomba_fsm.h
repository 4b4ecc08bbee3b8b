// The lab's Roomba behaviour as a finite state machine.
#pragma once

#include "roomba_rrt/behavior/roomba_behavior.h"
#include "roomba_rrt/fsm/state_machine.h"

namespace roomba_rrt::behavior {

/// Four states (ids = RoombaState values), starting in MoveForward:
///
///     MoveForward  --bump--> GoBack   --30 ticks--> Rotate --n ticks--> MoveForward
///     MoveForward  --180 ticks--> MoveInSpiral --1200 ticks--> MoveForward
///     MoveInSpiral --bump--> GoBack
///
/// Each tick: the current state checks its transition (bumper before timer), the machine enters
/// the new state if there is one, and the current state executes — a transition and the new
/// state's first command happen in the same tick, as in the lab.
class RoombaFsm final : public RoombaBehavior {
 public:
  RoombaFsm(const RoombaParams& params, std::uint32_t seed);

  robot::Velocity tick(const robot::BumperState& bumper) override {
    context_.bumper = bumper;
    machine_.update();
    return context_.cmd;
  }

  const fsm::StateMachine& machine() const { return machine_; }

 private:
  fsm::StateMachine machine_;
};

}  // namespace roomba_rrt::behavior
