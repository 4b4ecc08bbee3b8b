// A finite state machine: a set of states and the current one.
#pragma once

#include <memory>
#include <vector>

#include "roomba_rrt/fsm/state.h"

namespace roomba_rrt::fsm {

/// Owns its states and updates the current one. See State for the order of the hooks in one
/// update(). An update costs two virtual calls (three on a transition): no clock, lock or
/// allocation.
class StateMachine {
 public:
  /// Adds a state and returns its id (0, 1, 2, … in the order of the calls).
  StateId addState(std::unique_ptr<State> state);

  /// Makes `initial` the current state and enters it. std::out_of_range for an unknown id.
  void start(StateId initial);

  /// One update: check the transition, switch (entering the new state) if asked, execute.
  /// std::logic_error before start(), std::out_of_range for a transition to an unknown id.
  void update() {
    if (!current_) throwNotStarted();
    const StateId next = current_->checkTransition();
    if (next != kStay) changeState(next);
    current_->execute();
  }

  /// Switches to `id` and enters it (without executing it).
  void changeState(StateId id);

  StateId currentId() const { return current_id_; }
  const State& current() const { return *current_; }
  std::size_t size() const { return states_.size(); }
  const State& state(StateId id) const { return *states_.at(id); }

 private:
  [[noreturn]] static void throwNotStarted();

  std::vector<std::unique_ptr<State>> states_;
  State* current_ = nullptr;
  StateId current_id_ = kStay;
};

}  // namespace roomba_rrt::fsm
