// What the nodes and the coverage tool see of a Roomba behaviour, FSM or BT.
#pragma once

#include <cstdint>
#include <string>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::bt {
class Tree;
}

namespace roomba_rrt::behavior {

/// A Roomba behaviour ticked once per sample time: bumper in, (v, ω) out.
class RoombaBehavior {
 public:
  RoombaBehavior(const RoombaParams& params, std::uint32_t seed);
  virtual ~RoombaBehavior() = default;
  RoombaBehavior(const RoombaBehavior&) = delete;
  RoombaBehavior& operator=(const RoombaBehavior&) = delete;

  /// One tick (step 3 of the lab's simulation step): the bumper sensed in this step in, the
  /// command for this step out.
  virtual robot::Velocity tick(const robot::BumperState& bumper) = 0;

  /// The motion that produced the last command (the FSM's state, the BT's active leaf).
  RoombaState state() const { return context_.state; }
  /// Its name, for ~state: the FSM state's name, or the BT leaf's instance name ("Idle" before
  /// the first tick of a BT).
  const std::string& stateName() const { return *context_.state_name; }
  const RoombaParams& params() const { return params_; }

  /// New constants (dynamic_reconfigure): validated (util::InvalidInput naming the field, and
  /// nothing changes), then used by every motion that starts from now on; the motion running
  /// keeps its own until it ends, as the lab's rules say. The rate is the sample time the
  /// behaviour was started with and stays: `params.rate` is ignored.
  virtual void setParams(const RoombaParams& params);

  /// The behavior tree that makes the decisions, for monitors (Groot2, ~tree_status) and
  /// ~log_file; nullptr for the FSM.
  virtual bt::Tree* behaviorTree() { return nullptr; }

 protected:
  RoombaParams params_;
  RoombaContext context_;
};

}  // namespace roomba_rrt::behavior
