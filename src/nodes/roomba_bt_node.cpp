// roomba_bt: a behavior tree read from ~tree_file (default config/roomba_tree.xml, the lab's
// Roomba). A tree with navigation leaves (config/roomba_nav_tree.xml) runs as navigation behind
// move_base's interface (nav_behavior.h); see behavior_node.h for the rest.
#include "behavior_node.h"
#include "nav_behavior.h"
#include "roomba_rrt/behavior/roomba_bt.h"

int main(int argc, char** argv) {
  using roomba_rrt::behavior::RoombaBt;
  return roomba_rrt::nodes::runBehaviorNode(
      argc, argv, "roomba_bt",
      [](ros::NodeHandle& private_nh, const auto& params,
         std::uint32_t seed) -> std::unique_ptr<roomba_rrt::behavior::RoombaBehavior> {
        const std::string tree_file = private_nh.param<std::string>(
            "tree_file", roomba_rrt::nodes::packageConfigFile("roomba_tree.xml"));
        ROS_INFO("roomba_bt: tree from %s", tree_file.c_str());
        if (roomba_rrt::nav_node::isNavigationTree(tree_file)) {
          return roomba_rrt::nav_node::makeNavBehavior(private_nh, params, seed, tree_file);
        }
        return std::make_unique<RoombaBt>(params, seed, tree_file);
      });
}
