// PipelineSequence, RateController and RecoveryNode (the navigation tree's control nodes): one
// test per line of their header contracts.
#include <gtest/gtest.h>

#include "roomba_rrt/bt/pipeline_sequence.h"
#include "roomba_rrt/bt/rate_controller.h"
#include "roomba_rrt/bt/recovery_node.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, ScriptedLeaf

/// A PipelineSequence over three scripted children.
struct Pipeline {
  Pipeline(std::vector<Status> a, std::vector<Status> b, std::vector<Status> c) : node("pipe") {
    node.addChild(scripted(&first, std::move(a), "first"));
    node.addChild(scripted(&second, std::move(b), "second"));
    node.addChild(scripted(&third, std::move(c), "third"));
  }
  PipelineSequence node;
  ScriptedLeaf* first = nullptr;
  ScriptedLeaf* second = nullptr;
  ScriptedLeaf* third = nullptr;
};

TEST(PipelineSequence, success_ticks_the_next_child_in_the_same_tick) {
  Pipeline p({S}, {S}, {R});
  EXPECT_EQ(p.node.tick(), R);
  EXPECT_EQ(p.first->ticks, 1);
  EXPECT_EQ(p.second->ticks, 1);
  EXPECT_EQ(p.third->ticks, 1);
}

TEST(PipelineSequence, earlier_children_are_ticked_again_every_tick) {
  Pipeline p({S}, {S}, {R});
  for (int i = 0; i < 4; ++i) EXPECT_EQ(p.node.tick(), R);
  EXPECT_EQ(p.first->ticks, 4);
  EXPECT_EQ(p.second->ticks, 4);
  EXPECT_EQ(p.third->ticks, 4);
}

TEST(PipelineSequence, succeeds_after_the_last_child) {
  Pipeline p({S}, {S}, {R, S});
  EXPECT_EQ(p.node.tick(), R);
  EXPECT_EQ(p.node.tick(), S);
  EXPECT_FALSE(p.node.isRunning());
}

TEST(PipelineSequence, failure_halts_the_running_children_and_returns_failure) {
  Pipeline p({S, S, F}, {R}, {R});
  EXPECT_EQ(p.node.tick(), R);  // first S, second R (furthest)
  p.second->setNext(S);
  EXPECT_EQ(p.node.tick(), R);  // third reached and running
  EXPECT_TRUE(p.third->isRunning());
  EXPECT_EQ(p.node.tick(), F);  // first fails
  EXPECT_EQ(p.third->halts, 1);
  EXPECT_FALSE(p.third->isRunning());
  p.first->setNext(S);
  p.second->setNext(R);
  EXPECT_EQ(p.node.tick(), R);  // starts over: second is the furthest again
  EXPECT_EQ(p.third->ticks, 1);
}

TEST(PipelineSequence, the_furthest_running_child_returns_running) {
  Pipeline p({S}, {R}, {R});
  EXPECT_EQ(p.node.tick(), R);
  EXPECT_EQ(p.node.tick(), R);
  EXPECT_EQ(p.third->ticks, 0);
}

TEST(PipelineSequence, an_earlier_running_child_does_not_stop_a_later_one) {
  Pipeline p({S, R}, {S}, {R});
  EXPECT_EQ(p.node.tick(), R);  // reaches third
  EXPECT_EQ(p.node.tick(), R);  // first runs again (a replan), third is still ticked
  EXPECT_EQ(p.third->ticks, 2);
  EXPECT_EQ(p.second->ticks, 2);
}

/// A RateController over a scripted leaf, on its own tick clock.
struct Rate {
  Rate(std::vector<Status> script, double hz, double tick_rate)
      : node("rate", hz, tick_rate, clock) {
    node.setChild(scripted(&leaf, std::move(script)));
  }
  Status tick() {
    clock.advanceTick();
    return node.tick();
  }
  Blackboard clock;
  RateController node;
  ScriptedLeaf* leaf = nullptr;
};

TEST(RateController, the_period_is_the_tick_rate_over_hz) {
  Blackboard clock;
  EXPECT_EQ(RateController("r", 1.0, 60.0, clock).period(), 60);
  EXPECT_EQ(RateController("r", 20.0, 60.0, clock).period(), 3);
  EXPECT_EQ(RateController("r", 1000.0, 60.0, clock).period(), 1);
  EXPECT_THROW(RateController("r", 0.0, 60.0, clock), std::invalid_argument);
  EXPECT_THROW(RateController("r", std::nan(""), 60.0, clock), std::invalid_argument);
}

TEST(RateController, success_is_returned_then_held_until_a_period_passed) {
  Rate r({S}, 20.0, 60.0);  // every 3 ticks
  EXPECT_EQ(r.tick(), S);
  EXPECT_EQ(r.tick(), R);  // held: not ticked
  EXPECT_EQ(r.tick(), R);
  EXPECT_EQ(r.leaf->ticks, 1);
  EXPECT_EQ(r.tick(), S);  // third tick after the start: started again
  EXPECT_EQ(r.leaf->ticks, 2);
  EXPECT_EQ(r.leaf->enters, 2);
}

TEST(RateController, a_gap_in_the_ticks_starts_a_new_run_at_once) {
  Rate r({S}, 20.0, 60.0);
  EXPECT_EQ(r.tick(), S);
  r.clock.advanceTick();  // a tick in which the parent did not tick it
  EXPECT_EQ(r.tick(), S);
  EXPECT_EQ(r.leaf->ticks, 2);
}

TEST(RateController, failure_is_returned_and_the_next_tick_starts_a_new_run) {
  Rate r({F, S}, 20.0, 60.0);
  EXPECT_EQ(r.tick(), F);
  EXPECT_EQ(r.tick(), S);  // at once, not after a period
  EXPECT_EQ(r.leaf->ticks, 2);
}

TEST(RateController, a_running_child_is_ticked_on_every_tick) {
  Rate r({R, R, R, R, R, S}, 0.1, 60.0);  // period 600 ticks
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r.tick(), R);
  EXPECT_EQ(r.tick(), S);
  EXPECT_EQ(r.leaf->ticks, 6);
  EXPECT_EQ(r.leaf->enters, 1);
  EXPECT_EQ(r.tick(), R);  // now held for the rest of the period
  EXPECT_EQ(r.leaf->ticks, 6);
}

TEST(RateController, halt_halts_the_child_and_the_next_tick_starts_a_new_run) {
  Rate r({R}, 0.1, 60.0);
  EXPECT_EQ(r.tick(), R);
  r.node.halt();
  EXPECT_EQ(r.leaf->halts, 1);
  r.leaf->setNext(S);
  EXPECT_EQ(r.tick(), S);
  EXPECT_EQ(r.leaf->enters, 2);
}

/// A RecoveryNode over a scripted action and recovery.
struct Recovery {
  Recovery(std::vector<Status> a, std::vector<Status> r, int retries) : node("recovery", retries) {
    node.addChild(scripted(&action, std::move(a), "action"));
    node.addChild(scripted(&recovery, std::move(r), "recovery"));
  }
  RecoveryNode node;
  ScriptedLeaf* action = nullptr;
  ScriptedLeaf* recovery = nullptr;
};

TEST(RecoveryNode, action_success_and_running_are_returned) {
  Recovery t({R, S}, {S}, 1);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.node.tick(), S);
  EXPECT_EQ(t.recovery->ticks, 0);
}

TEST(RecoveryNode, action_failure_ticks_the_recovery_in_the_same_tick) {
  Recovery t({F}, {R}, 1);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.recovery->ticks, 1);
  EXPECT_EQ(t.node.tick(), R);  // the running recovery is ticked, not the action
  EXPECT_EQ(t.action->ticks, 1);
  EXPECT_EQ(t.recovery->ticks, 2);
}

TEST(RecoveryNode, recovery_success_retries_the_action_on_the_next_tick) {
  Recovery t({F, S}, {S}, 1);
  EXPECT_EQ(t.node.tick(), R);  // action fails, recovery succeeds
  EXPECT_EQ(t.action->ticks, 1);
  EXPECT_EQ(t.node.retries(), 1);
  EXPECT_EQ(t.node.tick(), S);  // action entered anew
  EXPECT_EQ(t.action->enters, 2);
}

TEST(RecoveryNode, gives_up_after_number_of_retries) {
  Recovery t({F}, {S}, 2);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.node.tick(), F);  // third failure, no recovery left
  EXPECT_EQ(t.recovery->ticks, 2);
  EXPECT_EQ(t.node.tick(), R);  // a new run has its recoveries again
  EXPECT_EQ(t.recovery->ticks, 3);
}

TEST(RecoveryNode, recovery_failure_returns_failure) {
  Recovery t({F}, {F}, 5);
  EXPECT_EQ(t.node.tick(), F);
  EXPECT_EQ(t.recovery->ticks, 1);
}

TEST(RecoveryNode, zero_retries_fails_with_the_action) {
  Recovery t({F}, {S}, 0);
  EXPECT_EQ(t.node.tick(), F);
  EXPECT_EQ(t.recovery->ticks, 0);
  EXPECT_THROW(RecoveryNode("r", -1), std::invalid_argument);
}

TEST(RecoveryNode, halt_halts_the_running_child) {
  Recovery t({F}, {R}, 1);
  EXPECT_EQ(t.node.tick(), R);
  t.node.halt();
  EXPECT_EQ(t.recovery->halts, 1);
  t.action->setNext(S);
  EXPECT_EQ(t.node.tick(), S);  // a halted node starts with the action
}

}  // namespace
}  // namespace roomba_rrt::bt
