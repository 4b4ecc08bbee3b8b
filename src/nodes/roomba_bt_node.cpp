// roomba_bt: a behavior tree read from ~tree_file (default config/roomba_tree.xml, the lab's
// Roomba). A tree with navigation or cleaning leaves (config/roomba_nav_tree.xml,
// config/roomba_coverage_tree.xml) runs as navigation behind move_base's interface
// (nav_behavior.h), and with ~unknown the cleaning tree cleans a home the robot explores and maps
// first; see behavior_node.h for the rest.
//
// `roomba_bt --tree-nodes-model` prints the BehaviorTree.CPP v4 <TreeNodesModel> of every node
// our trees can use (for Groot2) and exits, without a master; `roomba_bt --print-log FILE` prints
// a .btlog (BT.CPP's FileLogger2 format) as text.
#include <cstring>
#include <fstream>
#include <iostream>

#include "../ros/behavior_node.h"
#include "../ros/nav_behavior.h"
#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/bt/bt_log.h"
#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/navigation/nav_bt.h"

namespace {

/// Records the tree into `log_file` (~log_file: a .btlog, stamped with ROS time, so a run in
/// simulated time replays at its own pace).
void startLog(roomba_rrt::bt::Tree& tree, const std::string& log_file,
              const std::string& tree_file) {
  using roomba_rrt::util::InvalidInput;
  const std::string suffix = ".btlog";
  if (log_file.size() < suffix.size() ||
      log_file.compare(log_file.size() - suffix.size(), suffix.size(), suffix) != 0) {
    throw InvalidInput("~log_file",
                       "must end in .btlog (Groot2 opens only those), got '" + log_file + "'");
  }
  auto out = std::make_unique<std::ofstream>(log_file, std::ios::binary | std::ios::trunc);
  if (!*out) throw InvalidInput("~log_file", "cannot write '" + log_file + "'");
  std::string tree_id = tree_file.substr(tree_file.rfind('/') + 1);
  tree_id = tree_id.substr(0, tree_id.rfind('.'));
  tree.startLog(
      std::move(out), tree_id,
      roomba_rrt::navigation::treeNodesModel({roomba_rrt::coverage::coverageLeaves(nullptr)}),
      [] { return static_cast<std::int64_t>(ros::Time::now().toNSec() / 1000); });
  ROS_INFO("roomba_bt: recording the tree into %s", log_file.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--tree-nodes-model") == 0) {
      std::cout << roomba_rrt::navigation::treeNodesModel(
          {roomba_rrt::coverage::coverageLeaves(nullptr)});
      return 0;
    }
    if (std::strcmp(argv[i], "--print-log") == 0) {
      if (i + 1 >= argc) {
        std::cerr << "roomba_bt: --print-log needs a .btlog file\n";
        return 2;
      }
      try {
        roomba_rrt::bt::printBtLog(roomba_rrt::bt::readBtLogFile(argv[i + 1]), std::cout);
      } catch (const roomba_rrt::util::InvalidInput& error) {
        std::cerr << "roomba_bt: " << error.what() << '\n';
        return 1;
      }
      return 0;
    }
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::cout << "Usage: rosrun roomba_rrt roomba_bt [_tree_file:=FILE] [_param:=value ...]\n"
                   "       rosrun roomba_rrt roomba_bt --tree-nodes-model > nodes.xml\n"
                   "       rosrun roomba_rrt roomba_bt --print-log FILE.btlog\n"
                   "  --tree-nodes-model  print the BehaviorTree.CPP v4 <TreeNodesModel> of our\n"
                   "                      leaves and control nodes (Groot2 loads it) and exit\n"
                   "  --print-log FILE    print a .btlog (BehaviorTree.CPP's FileLogger2 format)\n"
                   "                      as text: time (s), node path, old -> new status\n"
                   "Parameters: doc/nodes.md (roomba_bt).\n";
      return 0;
    }
  }
  using roomba_rrt::behavior::RoombaBt;
  return roomba_rrt::nodes::runBehaviorNode(
      argc, argv, "roomba_bt",
      [](roomba_rrt::nodes::NodeParams& node_params, const auto& params, std::uint32_t seed,
         roomba_rrt::nodes::CommandOutput& output)
          -> std::unique_ptr<roomba_rrt::behavior::RoombaBehavior> {
        const std::string tree_file = node_params.get<std::string>(
            "tree_file", roomba_rrt::nodes::packageConfigFile("roomba_tree.xml"));
        ROS_INFO("roomba_bt: tree from %s", tree_file.c_str());
        const std::string log_file = node_params.get<std::string>("log_file", "");
        std::unique_ptr<roomba_rrt::behavior::RoombaBehavior> behavior;
        // ~unknown: exploring and cleaning a home it has never seen, with tree_file cleaning
        // once it has been explored (nav_behavior.h).
        if (node_params.get("unknown", false, /*write_back=*/false) ||
            roomba_rrt::navigation::usesNavigationLeaves(
                tree_file, {roomba_rrt::coverage::coverageLeaves(nullptr)})) {
          behavior =
              roomba_rrt::nav_node::makeNavBehavior(node_params, params, seed, tree_file, output);
        } else {
          behavior = std::make_unique<RoombaBt>(params, seed, tree_file);
        }
        if (!log_file.empty()) {
          if (behavior->behaviorTree() == nullptr) {
            throw roomba_rrt::util::InvalidInput(
                "~log_file", "cannot record with ~unknown (its trees change as the map grows)");
          }
          startLog(*behavior->behaviorTree(), log_file, tree_file);
        }
        return behavior;
      },
      roomba_rrt::navigation::treeNodesModel({roomba_rrt::coverage::coverageLeaves(nullptr)}));
}
