// The Roomba's leaves for the tree factory (the lab's tree is config/roomba_tree.xml).
#pragma once

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/bt/tree_factory.h"

namespace roomba_rrt::behavior {

/// Registers the leaves MoveForward, MoveInSpiral, GoBack and Rotate (no attributes; `name` sets
/// the name reported on ~state). The leaves read and write `context`, which must outlive the
/// trees built.
void registerRoombaLeaves(bt::TreeFactory& factory, const RoombaParams& params,
                          RoombaContext& context);

}  // namespace roomba_rrt::behavior
