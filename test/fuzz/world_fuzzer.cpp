// libFuzzer harness: world-file text → parseWorld → (if accepted) a simulator that builds its
// coverage grid and drives a few steps. Anything but a clean util::InvalidInput is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using roomba_rrt::sim::Simulator;
  roomba_rrt::world::World world;
  try {
    world = roomba_rrt::world::parseWorld(std::string(reinterpret_cast<const char*>(data), size),
                                          "fuzz.yaml");
  } catch (const roomba_rrt::util::InvalidInput&) {
    return 0;  // refused with a message naming the field: fine
  }
  Simulator simulator(world);
  for (int i = 0; i < 50; ++i)
    simulator.step({world.robot().max_linear_speed, 0.3 * world.robot().max_angular_speed});
  return 0;
}
