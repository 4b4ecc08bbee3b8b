#include "roomba_rrt/bt/sleep_node.h"

#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

SleepNode::SleepNode(std::string name, long ticks, const Blackboard& clock)
    : LeafNode(std::move(name)), clock_(clock), ticks_(static_cast<std::uint64_t>(ticks)) {
  if (ticks < 0) throw util::InvalidInput("ticks", "must be >= 0, got " + std::to_string(ticks));
}

}  // namespace roomba_rrt::bt
