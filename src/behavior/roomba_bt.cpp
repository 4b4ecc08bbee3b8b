#include "roomba_rrt/behavior/roomba_bt.h"

#include "roomba_rrt/behavior/lab_tree_xml.h"
#include "roomba_rrt/behavior/roomba_tree.h"

namespace roomba_rrt::behavior {
namespace {

bt::Tree buildTree(const RoombaParams& params, RoombaContext& context, const std::string& xml,
                   bool from_file) {
  bt::TreeFactory factory;
  factory.setTickRate(params.rate);  // RateController hz= in a tree file counts these ticks
  registerRoombaLeaves(factory, params, context);
  return from_file ? factory.buildFromFile(xml) : factory.buildFromText(xml, kLabTreeFile);
}

}  // namespace

RoombaBt::RoombaBt(const RoombaParams& params, std::uint32_t seed)
    : RoombaBt(params, seed, kLabTreeText, false) {}

RoombaBt::RoombaBt(const RoombaParams& params, std::uint32_t seed, const std::string& tree_file)
    : RoombaBt(params, seed, tree_file, true) {}

RoombaBt::RoombaBt(const RoombaParams& params, std::uint32_t seed, const std::string& xml,
                   bool from_file)
    : RoombaBehavior(params, seed), tree_(buildTree(params_, context_, xml, from_file)) {}

}  // namespace roomba_rrt::behavior
