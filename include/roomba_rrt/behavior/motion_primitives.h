// The lab's four motions, written once and used by both the FSM states and the BT leaves.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <type_traits>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::behavior {

/// What a motion wants to happen before it executes in this tick.
enum class MotionEvent : std::uint8_t {
  kNone,    ///< keep going: execute() gives this tick's command
  kBumped,  ///< the bumper is pressed (checked before the timer)
  kTimeUp,  ///< the motion has executed all its ticks
};

// Every motion has the same three calls, so an FSM state and a BT leaf are thin adapters:
//
//   enter()          start (again): the tick counter k goes back to 0
//   check(bumper)    kBumped / kTimeUp / kNone, without changing anything
//   execute()        the command for tick k, then k += 1
//
// Time is counted in ticks from entering (the lab counts executions × sample time).

/// Counts a motion's executions against its length in ticks.
class TickCounter {
 public:
  explicit TickCounter(long length) : length_(length) {}
  void restart() { k_ = 0; }
  bool done() const { return k_ >= length_; }
  /// The index of the current execution (0, 1, …), then advances.
  long next() { return k_++; }
  long length() const { return length_; }
  void setLength(long length) { length_ = length; }

 private:
  long length_;
  long k_ = 0;
};

/// kBumped when the bumper is pressed, else kTimeUp when `timer` is done (MoveForward,
/// MoveInSpiral: the bumper has priority over the timer).
inline MotionEvent bumperThenTimer(const robot::BumperState& bumper, const TickCounter& timer) {
  if (bumper.pressed) return MotionEvent::kBumped;
  return timer.done() ? MotionEvent::kTimeUp : MotionEvent::kNone;
}

/// kTimeUp when `timer` is done (GoBack, Rotate: the bumper is ignored).
inline MotionEvent timerOnly(const TickCounter& timer) {
  return timer.done() ? MotionEvent::kTimeUp : MotionEvent::kNone;
}

/// Driving straight at a fixed speed for a fixed number of ticks: MoveForward and GoBack.
/// `kStopsOnBump`: whether a pressed bumper ends the motion (checked before the timer).
template <bool kStopsOnBump>
class StraightMotion {
 public:
  StraightMotion(double speed, long ticks) : speed_(speed), timer_(ticks) {}
  void enter() { timer_.restart(); }
  MotionEvent check(const robot::BumperState& bumper) const {
    return kStopsOnBump ? bumperThenTimer(bumper, timer_) : timerOnly(timer_);
  }
  robot::Velocity execute() {
    timer_.next();
    return {speed_, 0.0};
  }

 private:
  double speed_;
  TickCounter timer_;
};

/// MoveForward: v = forward_speed, ω = 0, for round(move_forward_time·rate) ticks (180).
/// A bump ends it (→ GoBack), then the timer (→ MoveInSpiral).
class MoveForward : public StraightMotion<true> {
 public:
  explicit MoveForward(const RoombaParams& p)
      : StraightMotion(p.forward_speed, p.ticks(p.move_forward_time)) {}
};

/// MoveInSpiral: v = forward_speed, ω = v / r(t) with r(t) = r0 + b·t and t = k·Δt on its k-th
/// tick (k = 0, 1, …), for round(move_in_spiral_time·rate) ticks (1200). A bump ends it
/// (→ GoBack), then the timer (→ MoveForward). At k = 600, ω = 0.5 / 0.7 rad/s.
class MoveInSpiral {
 public:
  explicit MoveInSpiral(const RoombaParams& p)
      : speed_(p.forward_speed),
        r0_(p.initial_radius_spiral),
        growth_per_tick_(p.spiral_factor * p.sampleTime()),
        timer_(p.ticks(p.move_in_spiral_time)) {}
  void enter() { timer_.restart(); }
  MotionEvent check(const robot::BumperState& bumper) const {
    return bumperThenTimer(bumper, timer_);
  }
  robot::Velocity execute() {
    const double radius = r0_ + growth_per_tick_ * static_cast<double>(timer_.next());
    return {speed_, speed_ / radius};
  }

 private:
  double speed_;
  double r0_;
  double growth_per_tick_;
  TickCounter timer_;
};

/// GoBack: v = backward_speed, ω = 0, for round(go_back_time·rate) ticks (30 ticks at −0.1 m/s:
/// 5 cm). The bumper is ignored; the timer ends it (→ Rotate).
class GoBack : public StraightMotion<false> {
 public:
  explicit GoBack(const RoombaParams& p)
      : StraightMotion(p.backward_speed, p.ticks(p.go_back_time)) {}
};

/// Turning in place through a given angle dθ: at `speed` with the sign of dθ for
/// n = ⌈|dθ| / (speed·Δt)⌉ ticks, the last one slowed down so that the n ticks turn exactly dθ.
/// The bumper is ignored; the timer ends it. Rotate draws dθ, Spin is given it.
class TurnInPlace {
 public:
  TurnInPlace(double speed, double dt) : speed_(speed), dt_(dt), timer_(0) {}

  /// Starts a turn through `angle` (rad).
  void start(double angle);
  MotionEvent check(const robot::BumperState&) const { return timerOnly(timer_); }
  robot::Velocity execute() {
    const long k = timer_.next();
    return {0.0, k + 1 < timer_.length() ? full_ : last_};
  }

 private:
  double speed_;
  double dt_;
  TickCounter timer_;
  double full_ = 0;  ///< ω of every tick but the last
  double last_ = 0;  ///< ω of the last tick
};

/// Rotate: on enter, draws dθ ∈ [−π, π) (drawAngle) and turns in place through it at
/// angular_speed (TurnInPlace). The bumper is ignored; the timer ends it (→ MoveForward).
class Rotate {
 public:
  Rotate(const RoombaParams& p, std::mt19937& rng)
      : turn_(p.angular_speed, p.sampleTime()), rng_(rng) {}

  /// The documented draw, identical in the FSM and the BT: one 32-bit output u of the
  /// std::mt19937 (fully specified by the C++ standard), dθ = −π + 2π·u / 2³².
  static double drawAngle(std::mt19937& rng);

  void enter() { turn_.start(drawAngle(rng_)); }
  MotionEvent check(const robot::BumperState& bumper) const { return turn_.check(bumper); }
  robot::Velocity execute() { return turn_.execute(); }

 private:
  TurnInPlace turn_;
  std::mt19937& rng_;
};

/// Spin (navigation recovery, Nav2's name): turns in place through a fixed `angle` at `speed`
/// (TurnInPlace) each time it is entered. The bumper is ignored; the timer ends it.
class Spin {
 public:
  Spin(double angle, double speed, double dt) : turn_(speed, dt), angle_(angle) {}
  void enter() { turn_.start(angle_); }
  MotionEvent check(const robot::BumperState& bumper) const { return turn_.check(bumper); }
  robot::Velocity execute() { return turn_.execute(); }

 private:
  TurnInPlace turn_;
  double angle_;
};

/// BackUp (navigation recovery, Nav2's name): GoBack's straight motion, `distance` backwards at
/// `speed` (> 0) for round(distance / speed · rate) ticks. The bumper is ignored.
class BackUp : public StraightMotion<false> {
 public:
  BackUp(double distance, double speed, double rate)
      : StraightMotion(-speed, std::lround(distance / speed * rate)) {}
};

/// A motion as an FSM state or BT leaf holds it (MotionState, MotionLeaf). The lab's four motions
/// are built from RoombaParams (Rotate also from the context's generator): when the context's
/// parameters changed since the motion was built (RoombaBehavior::setParams), enter() rebuilds it
/// from them first, so a change takes effect when a motion starts, never in the middle of one.
/// The navigation's BackUp and Spin, built from their ports, keep what they were built with.
template <class Motion>
class MotionHolder {
 public:
  explicit MotionHolder(Motion motion) : motion_(std::move(motion)) {}

  /// Starts the motion, rebuilt first if the context's parameters changed.
  template <class Context>
  Motion& enter(Context& context) {
    if constexpr (std::is_constructible_v<Motion, const RoombaParams&>) {
      if (context.params && context.params_version != version_) {
        motion_.emplace(*context.params);
        version_ = context.params_version;
      }
    } else if constexpr (std::is_constructible_v<Motion, const RoombaParams&, std::mt19937&>) {
      if (context.params && context.params_version != version_) {
        motion_.emplace(*context.params, context.rng);
        version_ = context.params_version;
      }
    }
    motion_->enter();
    return *motion_;
  }
  Motion& operator*() { return *motion_; }
  Motion* operator->() { return &*motion_; }

 private:
  std::optional<Motion> motion_;  // optional: Rotate holds a reference and cannot be assigned
  std::uint64_t version_ = 0;     // the context's params_version it was built with
};

}  // namespace roomba_rrt::behavior
