// Sequence, Selector and their reactive variants: one test per line of their header contracts.
#include <gtest/gtest.h>

#include "roomba_rrt/bt/reactive_selector.h"
#include "roomba_rrt/bt/reactive_sequence.h"
#include "roomba_rrt/bt/selector_node.h"
#include "roomba_rrt/bt/sequence_node.h"
#include "roomba_rrt/bt/tree.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, ScriptedLeaf

TEST(Sequence, success_enters_and_ticks_the_next_child_in_the_same_tick) {
  TwoChildren<SequenceNode> t({S}, {R});
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 1);
  EXPECT_EQ(t.second->enters, 1);
  EXPECT_EQ(t.second->ticks, 1);
}

TEST(Sequence, remembers_the_running_child_without_rechecking_earlier_ones) {
  TwoChildren<SequenceNode> t({S}, {R});
  for (int i = 0; i < 5; ++i) EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 1);
  EXPECT_EQ(t.second->ticks, 5);
  EXPECT_EQ(t.second->enters, 1);
}

TEST(Sequence, succeeds_after_the_last_child_and_restarts_from_the_first) {
  TwoChildren<SequenceNode> t({S}, {R, S});
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.node.tick(), S);
  EXPECT_FALSE(t.node.isRunning());
  t.second->setNext(R);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 2);
  EXPECT_EQ(t.second->enters, 2);
}

TEST(Sequence, failure_returns_at_once_and_the_next_tick_starts_from_the_first) {
  TwoChildren<SequenceNode> t({F}, {R});
  EXPECT_EQ(t.node.tick(), F);
  EXPECT_EQ(t.second->ticks, 0);
  t.first->setNext(S);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 2);
}

TEST(Sequence, halt_halts_the_running_child_and_rewinds) {
  TwoChildren<SequenceNode> t({S}, {R});
  t.node.tick();
  t.node.halt();
  EXPECT_EQ(t.second->halts, 1);
  EXPECT_EQ(t.first->halts, 0);  // it had finished: nothing to halt
  t.node.tick();
  EXPECT_EQ(t.first->ticks, 2);
  EXPECT_EQ(t.second->enters, 2);
}

TEST(Selector, failure_enters_and_ticks_the_next_child_in_the_same_tick) {
  TwoChildren<SelectorNode> t({F}, {R});
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.second->enters, 1);
}

TEST(Selector, remembers_the_running_child_without_rechecking_earlier_ones) {
  TwoChildren<SelectorNode> t({F}, {R});
  for (int i = 0; i < 5; ++i) EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 1);
  EXPECT_EQ(t.second->ticks, 5);
}

TEST(Selector, success_returns_at_once_and_the_next_tick_starts_from_the_first) {
  TwoChildren<SelectorNode> t({F}, {R, S});
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.node.tick(), S);
  t.first->setNext(R);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 2);
  EXPECT_EQ(t.second->ticks, 2);
}

TEST(Selector, fails_after_the_last_child_fails) {
  TwoChildren<SelectorNode> t({F}, {F});
  EXPECT_EQ(t.node.tick(), F);
  EXPECT_EQ(t.second->ticks, 1);
}

TEST(Tree, a_finished_root_starts_again_from_the_left_on_the_next_tick) {
  auto root = std::make_unique<SequenceNode>("root");
  ScriptedLeaf *a, *b;
  root->addChild(scripted(&a, {S}));
  root->addChild(scripted(&b, {S}));
  Tree tree(std::move(root));
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(a->enters, 2);
  EXPECT_EQ(b->enters, 2);
}

TEST(ReactiveSequence, rechecks_earlier_children_every_tick) {
  TwoChildren<ReactiveSequence> t({S}, {R});
  for (int i = 0; i < 3; ++i) EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.first->ticks, 3);
  EXPECT_EQ(t.first->enters, 3);  // it finishes each time, so it is entered anew
  EXPECT_EQ(t.second->enters, 1);
}

TEST(ReactiveSequence, halts_the_running_child_when_an_earlier_child_fails) {
  TwoChildren<ReactiveSequence> t({S}, {R});
  t.node.tick();
  t.first->setNext(F);
  EXPECT_EQ(t.node.tick(), F);
  EXPECT_EQ(t.second->halts, 1);
}

TEST(ReactiveSequence, halts_the_running_child_when_an_earlier_child_runs_again) {
  TwoChildren<ReactiveSequence> t({S}, {R});
  t.node.tick();
  t.first->setNext(R);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.second->halts, 1);
  EXPECT_EQ(t.second->ticks, 1);
}

TEST(ReactiveSelector, a_higher_priority_child_preempts_the_running_one) {
  TwoChildren<ReactiveSelector> t({F}, {R});
  EXPECT_EQ(t.node.tick(), R);
  t.first->setNext(R);
  EXPECT_EQ(t.node.tick(), R);
  EXPECT_EQ(t.second->halts, 1);
}

TEST(ReactiveSelector, success_of_an_earlier_child_halts_the_running_one) {
  TwoChildren<ReactiveSelector> t({F}, {R});
  t.node.tick();
  t.first->setNext(S);
  EXPECT_EQ(t.node.tick(), S);
  EXPECT_EQ(t.second->halts, 1);
}

TEST(ReactiveSelector, fails_when_every_child_fails) {
  TwoChildren<ReactiveSelector> t({F}, {F});
  EXPECT_EQ(t.node.tick(), F);
  EXPECT_EQ(t.first->ticks, 1);
  EXPECT_EQ(t.second->ticks, 1);
}

TEST(Composites, an_impossible_child_status_is_an_error) {
  const auto impossible = static_cast<Status>(7);
  TwoChildren<SequenceNode> sequence({impossible}, {R});
  EXPECT_THROW(sequence.node.tick(), std::logic_error);
  TwoChildren<SelectorNode> selector({impossible}, {R});
  EXPECT_THROW(selector.node.tick(), std::logic_error);
  TwoChildren<ReactiveSequence> reactive({impossible}, {R});
  EXPECT_THROW(reactive.node.tick(), std::logic_error);
  TwoChildren<ReactiveSelector> reactive_selector({impossible}, {R});
  EXPECT_THROW(reactive_selector.node.tick(), std::logic_error);
}

}  // namespace
}  // namespace roomba_rrt::bt
