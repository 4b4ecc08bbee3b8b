// The lab's Roomba behaviour as a behavior tree.
#pragma once

#include <string>

#include "roomba_rrt/behavior/roomba_behavior.h"
#include "roomba_rrt/bt/tree.h"

namespace roomba_rrt::behavior {

/// A behavior tree of Roomba leaves, by default the lab's (config/roomba_tree.xml, compiled in), or
/// one read from a tree file (bt::TreeFileError naming the element and line when it is invalid).
///
/// **The idle tick.** Each tick starts with a zero command; the leaf that runs writes its
/// command. When the root finishes (SUCCESS: MoveInSpiral's or Rotate's time is up; FAILURE:
/// nothing could run), no leaf runs in that tick, so the robot gets (0, 0) for one tick and the
/// bumper of that tick is not looked at; the next tick enters the root again from the left.
/// Leaving out those idle ticks, the BT produces exactly the FSM's commands for the same
/// sequence of bumper readings and seed (the idle tick's reading is not consumed), as long as
/// the bumper is not pressed on the tick Rotate finishes (the FSM's MoveForward drives on
/// there without looking; a robot turning in place after backing off is not pressed).
class RoombaBt final : public RoombaBehavior {
 public:
  /// The lab's tree (config/roomba_tree.xml as it was at build time).
  RoombaBt(const RoombaParams& params, std::uint32_t seed);
  /// The tree in `tree_file` (XML, see bt::TreeFactory).
  RoombaBt(const RoombaParams& params, std::uint32_t seed, const std::string& tree_file);

  robot::Velocity tick(const robot::BumperState& bumper) override {
    context_.bumper = bumper;
    context_.cmd = robot::Velocity{};
    idle_ = tree_.tick() != bt::Status::kRunning;
    return context_.cmd;
  }

  /// True when the last tick was an idle tick (the root finished).
  bool lastTickIdle() const { return idle_; }
  bt::Tree& tree() { return tree_; }
  bt::Tree* behaviorTree() override { return &tree_; }

 private:
  /// `xml` is the file's text when `from_file` is false.
  RoombaBt(const RoombaParams& params, std::uint32_t seed, const std::string& xml, bool from_file);

  bt::Tree tree_;
  bool idle_ = false;
};

}  // namespace roomba_rrt::behavior
