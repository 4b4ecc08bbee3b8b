#include "roomba_rrt/fsm/state_machine.h"

#include <stdexcept>
#include <string>

namespace roomba_rrt::fsm {

StateId StateMachine::addState(std::unique_ptr<State> state) {
  if (!state) throw std::invalid_argument("StateMachine::addState: the state is null");
  states_.push_back(std::move(state));
  return states_.size() - 1;
}

void StateMachine::start(StateId initial) { changeState(initial); }

void StateMachine::changeState(StateId id) {
  if (id >= states_.size()) {
    throw std::out_of_range("StateMachine: transition to unknown state id " + std::to_string(id) +
                            " (" + std::to_string(states_.size()) + " states)");
  }
  current_ = states_[id].get();
  current_id_ = id;
  current_->enter();
}

void StateMachine::throwNotStarted() {
  throw std::logic_error("StateMachine::update called before start()");
}

}  // namespace roomba_rrt::fsm
