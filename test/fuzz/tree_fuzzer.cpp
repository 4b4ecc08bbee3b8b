// libFuzzer harness: behavior-tree XML → TreeFactory (public API, the Roomba's leaves
// registered) → (if accepted) a few hundred ticks with the bumper pressed now and then.
#include <cstddef>
#include <cstdint>
#include <string>

#include "roomba_rrt/behavior/roomba_tree.h"
#include "roomba_rrt/bt/tree_factory.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomba_rrt;
  const behavior::RoombaParams params;
  behavior::RoombaContext context(1);
  bt::TreeFactory factory;
  factory.setNoticeHandler({});  // v3 spellings are fine here; printing them would slow fuzzing
  behavior::registerRoombaLeaves(factory, params, context);
  try {
    bt::Tree tree =
        factory.buildFromText(std::string(reinterpret_cast<const char*>(data), size), "fuzz.xml");
    for (int i = 0; i < 300; ++i) {
      context.bumper.pressed = context.bumper.left = (i % 41 == 0);
      tree.tick();
    }
    tree.halt();
  } catch (const bt::TreeFileError&) {  // the factory's documented error: a bad tree file
  }
  return 0;
}
