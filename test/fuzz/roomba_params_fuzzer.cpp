// libFuzzer harness: behaviour-parameter text → parseRoombaParams → (if accepted) the FSM ticks
// through its motions with the bumper pressed now and then. Anything but a clean util::InvalidInput
// is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "roomba_rrt/behavior/roomba_fsm.h"
#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/util/invalid_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomba_rrt;
  behavior::RoombaParams params;
  try {
    params = behavior::parseRoombaParams(std::string(reinterpret_cast<const char*>(data), size),
                                         "fuzz.yaml");
  } catch (const util::InvalidInput&) {
    return 0;
  }
  behavior::RoombaFsm fsm(params, 1);
  robot::BumperState bumper;
  for (int i = 0; i < 200; ++i) {
    bumper.pressed = bumper.left = (i % 37 == 0);
    fsm.tick(bumper);
  }
  return 0;
}
