#include "roomba_rrt/behavior/roomba_tree.h"

#include <memory>

#include "roomba_rrt/behavior/motion_leaf.h"

namespace roomba_rrt::behavior {

namespace {

template <class Motion>
bt::TreeFactory::Builder leaf(RoombaState id, Motion prototype, RoombaContext& context) {
  return [id, prototype, &context](const bt::NodeSpec& spec) {
    return std::make_unique<MotionLeaf<Motion>>(spec.name, id, prototype, context);
  };
}

}  // namespace

void registerRoombaLeaves(bt::TreeFactory& factory, const RoombaParams& params,
                          RoombaContext& context) {
  const auto add = [&](RoombaState id, bt::TreeFactory::Builder builder) {
    factory.registerLeaf(toString(id), std::move(builder));
  };
  add(RoombaState::kMoveForward, leaf(RoombaState::kMoveForward, MoveForward(params), context));
  add(RoombaState::kMoveInSpiral, leaf(RoombaState::kMoveInSpiral, MoveInSpiral(params), context));
  add(RoombaState::kGoBack, leaf(RoombaState::kGoBack, GoBack(params), context));
  add(RoombaState::kRotate, leaf(RoombaState::kRotate, Rotate(params, context.rng), context));
}

}  // namespace roomba_rrt::behavior
