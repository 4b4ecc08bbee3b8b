#include "roomba_rrt/behavior/roomba_state.h"

namespace roomba_rrt::behavior {

const char* toString(RoombaState state) {
  switch (state) {
    case RoombaState::kMoveForward:
      return "MoveForward";
    case RoombaState::kMoveInSpiral:
      return "MoveInSpiral";
    case RoombaState::kGoBack:
      return "GoBack";
    case RoombaState::kRotate:
      return "Rotate";
  }
  return "Invalid";
}

void retuneMotions(RoombaParams& in_force, const RoombaParams& requested, RoombaContext& context) {
  RoombaParams next = requested;
  next.rate = in_force.rate;
  validate(next);
  in_force = next;
  ++context.params_version;
}

}  // namespace roomba_rrt::behavior
