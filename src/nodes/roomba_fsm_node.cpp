// roomba_fsm: the lab's Roomba behaviour as a finite state machine (see behavior_node.h).
#include "../ros/behavior_node.h"
#include "roomba_rrt/behavior/roomba_fsm.h"

int main(int argc, char** argv) {
  if (roomba_rrt::nodes::printedHelp(argc, argv, "roomba_fsm",
                                     "The lab's Roomba behaviour as a finite state machine: "
                                     "bumper and odom in, cmd_vel out.")) {
    return 0;
  }
  using roomba_rrt::behavior::RoombaFsm;
  return roomba_rrt::nodes::runBehaviorNode(
      argc, argv, "roomba_fsm",
      [](roomba_rrt::nodes::NodeParams&, const auto& params, std::uint32_t seed, auto&) {
        return std::make_unique<RoombaFsm>(params, seed);
      });
}
