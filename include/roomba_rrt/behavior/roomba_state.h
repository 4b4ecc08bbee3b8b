// The four motions of the lab's Roomba and what the FSM states and BT leaves share.
#pragma once

#include <cstdint>
#include <random>
#include <string>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::behavior {

/// The lab's four motions: the FSM's states and the BT's leaves.
enum class RoombaState : std::uint8_t { kMoveForward, kMoveInSpiral, kGoBack, kRotate };

/// "MoveForward", "MoveInSpiral", "GoBack" or "Rotate".
const char* toString(RoombaState state);

/// The data the states (FSM) or leaves (BT) of one Roomba behaviour share, like the lab's
/// `agent`: the bumper of this tick in, the command of this tick out, and the random generator
/// of the rotation angle.
struct RoombaContext {
  explicit RoombaContext(std::uint32_t seed) : rng(seed) {}

  robot::BumperState bumper;  ///< input: the bumper sensed in this step
  robot::Velocity cmd;        ///< output: the command decided in this tick
  /// The motion that produced `cmd` (the last one that executed).
  RoombaState state = RoombaState::kMoveForward;
  /// Its name: the FSM state's, or the BT leaf's instance name.
  const std::string* state_name = nullptr;
  std::mt19937 rng;  ///< Rotate's angle generator (see Rotate::drawAngle)
  /// The constants the lab's motions are built from when they start (RoombaBehavior::setParams
  /// changes them between motions), and how often they changed: a motion built with an older
  /// version is rebuilt when it is next entered. Null: the motions keep what they were built with.
  const RoombaParams* params = nullptr;
  std::uint64_t params_version = 0;
};

/// Makes `requested` the constants in force (`in_force`, which context.params points to) for the
/// motions that start from now on, keeping the sample time (`rate`) of `in_force`.
/// util::InvalidInput naming the field, and nothing changes, when they are invalid.
void retuneMotions(RoombaParams& in_force, const RoombaParams& requested, RoombaContext& context);

}  // namespace roomba_rrt::behavior
