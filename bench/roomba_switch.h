// The lab's Roomba behaviour as one hand-written `switch`: the baseline the FSM and BT engines
// are measured against (bench/behavior_bench.cpp). ROS-free, header-only.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "roomba_rrt/behavior/motion_primitives.h"
#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::bench {

/// The same logic as behavior::RoombaFsm, tick for tick (same commands, same rotation angles
/// for the same seed), written as the plain state machine a C programmer would write: one enum,
/// one counter, one switch to check the transition and one to execute. No engine, no virtual
/// call. behavior_bench checks that it agrees with RoombaFsm before it measures.
class RoombaSwitch {
 public:
  using State = behavior::RoombaState;

  RoombaSwitch(const behavior::RoombaParams& p, std::uint32_t seed)
      : forward_speed_(p.forward_speed),
        backward_speed_(p.backward_speed),
        angular_speed_(p.angular_speed),
        r0_(p.initial_radius_spiral),
        growth_per_tick_(p.spiral_factor * p.sampleTime()),
        dt_(p.sampleTime()),
        forward_ticks_(p.ticks(p.move_forward_time)),
        spiral_ticks_(p.ticks(p.move_in_spiral_time)),
        back_ticks_(p.ticks(p.go_back_time)),
        rng_(seed) {}

  robot::Velocity tick(const robot::BumperState& bumper) {
    switch (state_) {  // check the transition: bumper first, then the time
      case State::kMoveForward:
        if (bumper.pressed) {
          enter(State::kGoBack);
        } else if (k_ >= forward_ticks_) {
          enter(State::kMoveInSpiral);
        }
        break;
      case State::kMoveInSpiral:
        if (bumper.pressed) {
          enter(State::kGoBack);
        } else if (k_ >= spiral_ticks_) {
          enter(State::kMoveForward);
        }
        break;
      case State::kGoBack:
        if (k_ >= back_ticks_) enter(State::kRotate);
        break;
      case State::kRotate:
        if (k_ >= rotate_ticks_) enter(State::kMoveForward);
        break;
    }
    const long k = k_++;
    switch (state_) {  // execute, in the same tick
      case State::kMoveForward:
        return {forward_speed_, 0.0};
      case State::kMoveInSpiral:
        return {forward_speed_, forward_speed_ / (r0_ + growth_per_tick_ * k)};
      case State::kGoBack:
        return {backward_speed_, 0.0};
      case State::kRotate:
        return {0.0, k + 1 < rotate_ticks_ ? rotate_w_ : last_rotate_w_};
    }
    return {};
  }

  State state() const { return state_; }

 private:
  void enter(State next) {
    state_ = next;
    k_ = 0;
    if (next != State::kRotate) return;
    // The documented draw shared with the engines, then ⌈|dθ| / (ωΔt)⌉ ticks, the last trimmed.
    const double angle = behavior::Rotate::drawAngle(rng_);
    const double step = angular_speed_ * dt_;
    rotate_ticks_ = static_cast<long>(std::ceil(std::fabs(angle) / step));
    rotate_w_ = std::copysign(angular_speed_, angle);
    last_rotate_w_ = rotate_ticks_ > 0
                         ? std::copysign(std::fabs(angle) - (rotate_ticks_ - 1) * step, angle) / dt_
                         : 0.0;
  }

  double forward_speed_, backward_speed_, angular_speed_, r0_, growth_per_tick_, dt_;
  long forward_ticks_, spiral_ticks_, back_ticks_;
  std::mt19937 rng_;
  State state_ = State::kMoveForward;
  long k_ = 0;
  long rotate_ticks_ = 0;
  double rotate_w_ = 0, last_rotate_w_ = 0;
};

}  // namespace roomba_rrt::bench
