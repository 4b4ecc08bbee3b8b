// A state of a finite state machine.
#pragma once

#include <cstddef>
#include <string>

namespace roomba_rrt::fsm {

/// Index of a state in its StateMachine (the order of StateMachine::addState()).
using StateId = std::size_t;
/// checkTransition()'s answer for "stay in this state".
inline constexpr StateId kStay = static_cast<StateId>(-1);

/// One state, with three hooks. The state machine calls, on every update of the current state:
///
/// 1. checkTransition(): return the id of the next state, or kStay;
/// 2. if it returned another state: that state's enter();
/// 3. execute() of the (possibly new) current state — a transition and the new state's first
///    execution happen in the same update. (This is the rule of the CT-213 lab's state machine:
///    the Roomba FSM built on this engine must tick exactly like the lab's, and like the
///    equivalent behaviour tree.)
///
/// States reach the data they act on (sensor readings, the command they produce) through
/// references they are constructed with, so the hooks take no arguments.
class State {
 public:
  explicit State(std::string name) : name_(std::move(name)) {}
  virtual ~State() = default;
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  /// Called when the machine switches to this state (also for a self-transition) and at start().
  virtual void enter() {}
  /// Decides whether to leave the state before this update's execute(). Default: stay.
  virtual StateId checkTransition() { return kStay; }
  /// The state's action for one update.
  virtual void execute() = 0;

  const std::string& name() const { return name_; }

 private:
  std::string name_;
};

}  // namespace roomba_rrt::fsm
