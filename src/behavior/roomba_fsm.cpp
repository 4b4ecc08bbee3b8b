#include "roomba_rrt/behavior/roomba_fsm.h"

#include <memory>

#include "roomba_rrt/behavior/motion_state.h"

namespace roomba_rrt::behavior {
namespace {

constexpr fsm::StateId id(RoombaState state) { return static_cast<fsm::StateId>(state); }

}  // namespace

RoombaFsm::RoombaFsm(const RoombaParams& params, std::uint32_t seed)
    : RoombaBehavior(params, seed) {
  const fsm::StateId forward = id(RoombaState::kMoveForward);
  const fsm::StateId spiral = id(RoombaState::kMoveInSpiral);
  const fsm::StateId back = id(RoombaState::kGoBack);
  const fsm::StateId rotate = id(RoombaState::kRotate);
  // Added in the order of the RoombaState values, so that ids and enum values agree.
  machine_.addState(std::make_unique<MotionState<MoveForward>>(
      RoombaState::kMoveForward, MoveForward(params_), context_, back, spiral));
  machine_.addState(std::make_unique<MotionState<MoveInSpiral>>(
      RoombaState::kMoveInSpiral, MoveInSpiral(params_), context_, back, forward));
  machine_.addState(std::make_unique<MotionState<GoBack>>(RoombaState::kGoBack, GoBack(params_),
                                                          context_, fsm::kStay, rotate));
  machine_.addState(std::make_unique<MotionState<Rotate>>(
      RoombaState::kRotate, Rotate(params_, context_.rng), context_, fsm::kStay, forward));
  machine_.start(forward);
  context_.state_name = &machine_.current().name();
}

}  // namespace roomba_rrt::behavior
