// The FSM engine: hook order, same-tick transitions, errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "roomba_rrt/fsm/state_machine.h"

namespace roomba_rrt::fsm {
namespace {

/// Records every hook call into a shared log; leaves for `next` after `stay_for` checks.
class LoggingState final : public State {
 public:
  LoggingState(std::string name, std::vector<std::string>& log, int stay_for, StateId next)
      : State(std::move(name)), log_(log), stay_for_(stay_for), next_(next) {}
  void enter() override {
    log_.push_back(name() + ".enter");
    checks_ = 0;
  }
  StateId checkTransition() override {
    log_.push_back(name() + ".check");
    return ++checks_ > stay_for_ ? next_ : kStay;
  }
  void execute() override { log_.push_back(name() + ".execute"); }

 private:
  std::vector<std::string>& log_;
  int stay_for_;
  StateId next_;
  int checks_ = 0;
};

TEST(StateMachine, transition_and_new_state_execute_happen_in_the_same_update) {
  std::vector<std::string> log;
  StateMachine machine;
  const StateId a = machine.addState(std::make_unique<LoggingState>("A", log, 1, 1));
  machine.addState(std::make_unique<LoggingState>("B", log, 100, 0));
  machine.start(a);
  machine.update();
  machine.update();
  EXPECT_EQ(log, (std::vector<std::string>{"A.enter", "A.check", "A.execute", "A.check", "B.enter",
                                           "B.execute"}));
  EXPECT_EQ(machine.current().name(), "B");
  EXPECT_EQ(machine.currentId(), 1u);
}

TEST(StateMachine, a_self_transition_enters_the_state_again) {
  std::vector<std::string> log;
  StateMachine machine;
  machine.addState(std::make_unique<LoggingState>("A", log, 0, 0));
  machine.start(0);
  machine.update();
  EXPECT_EQ(log, (std::vector<std::string>{"A.enter", "A.check", "A.enter", "A.execute"}));
}

TEST(StateMachine, update_before_start_is_an_error) {
  StateMachine machine;
  EXPECT_THROW(machine.update(), std::logic_error);
}

TEST(StateMachine, a_transition_to_an_unknown_state_is_an_error) {
  std::vector<std::string> log;
  StateMachine machine;
  machine.addState(std::make_unique<LoggingState>("A", log, 0, 7));
  machine.start(0);
  EXPECT_THROW(machine.update(), std::out_of_range);
  EXPECT_THROW(machine.start(3), std::out_of_range);
}

}  // namespace
}  // namespace roomba_rrt::fsm
