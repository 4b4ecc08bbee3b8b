// roomba_bt: the lab's Roomba behaviour as a behavior tree read from ~tree_file (default
// config/roomba_tree.xml); see behavior_node.h for the rest.
#include "behavior_node.h"
#include "roomba_rrt/behavior/roomba_bt.h"

int main(int argc, char** argv) {
  using roomba_rrt::behavior::RoombaBt;
  return roomba_rrt::nodes::runBehaviorNode(
      argc, argv, "roomba_bt",
      [](ros::NodeHandle& private_nh, const auto& params, std::uint32_t seed) {
        const std::string tree_file = private_nh.param<std::string>(
            "tree_file", roomba_rrt::nodes::packageConfigFile("roomba_tree.xml"));
        ROS_INFO("roomba_bt: tree from %s", tree_file.c_str());
        return std::make_unique<RoombaBt>(params, seed, tree_file);
      });
}
