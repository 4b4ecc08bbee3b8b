// The Roomba's leaves for the tree factory, and the lab's tree.
#pragma once

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/bt/tree_factory.h"

namespace roomba_rrt::behavior {

/// The lab's tree (config/roomba_tree.xml holds the same text):
///
///     Fallback
///     ├── Sequence "clean":   MoveForward, MoveInSpiral
///     └── Sequence "recover": GoBack, Rotate
extern const char* const kLabTreeXml;

/// Registers the leaves MoveForward, MoveInSpiral, GoBack and Rotate (no attributes; `name` sets
/// the name reported on ~state). The leaves read and write `context`, which must outlive the
/// trees built.
void registerRoombaLeaves(bt::TreeFactory& factory, const RoombaParams& params,
                          RoombaContext& context);

}  // namespace roomba_rrt::behavior
