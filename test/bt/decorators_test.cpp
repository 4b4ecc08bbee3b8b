// Inverter, Repeat, Retry and Timeout: one test per line of their header contracts.
#include <gtest/gtest.h>

#include "roomba_rrt/bt/inverter_node.h"
#include "roomba_rrt/bt/repeat_node.h"
#include "roomba_rrt/bt/retry_node.h"
#include "roomba_rrt/bt/timeout_node.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, ScriptedLeaf

TEST(Inverter, swaps_success_and_failure_and_keeps_running) {
  ScriptedLeaf* leaf;
  auto inverter = decorate<InverterNode>(&leaf, {S, F, R});
  EXPECT_EQ(inverter->tick(), F);
  EXPECT_EQ(inverter->tick(), S);
  EXPECT_EQ(inverter->tick(), R);
}

TEST(Repeat, runs_the_child_num_cycles_times_one_cycle_per_tick) {
  ScriptedLeaf* leaf;
  auto repeat = decorate<RepeatNode>(&leaf, {S}, 3);
  EXPECT_EQ(repeat->tick(), R);
  EXPECT_EQ(repeat->tick(), R);
  EXPECT_EQ(repeat->tick(), S);
  EXPECT_EQ(leaf->enters, 3);
  EXPECT_EQ(repeat->tick(), R);  // a new run counts from zero
}

TEST(Repeat, fails_when_the_child_fails) {
  ScriptedLeaf* leaf;
  auto repeat = decorate<RepeatNode>(&leaf, {S, F}, -1);
  EXPECT_EQ(repeat->tick(), R);
  EXPECT_EQ(repeat->tick(), F);
}

TEST(Repeat, forever_never_succeeds) {
  ScriptedLeaf* leaf;
  auto repeat = decorate<RepeatNode>(&leaf, {S}, -1);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(repeat->tick(), R);
}

TEST(Repeat, rejects_a_zero_cycle_count) {
  EXPECT_THROW(RepeatNode("r", 0), std::invalid_argument);
}

TEST(Retry, tries_again_on_the_next_tick_after_a_failure) {
  ScriptedLeaf* leaf;
  auto retry = decorate<RetryNode>(&leaf, {F, F, S}, 3);
  EXPECT_EQ(retry->tick(), R);
  EXPECT_EQ(retry->tick(), R);
  EXPECT_EQ(retry->tick(), S);
  EXPECT_EQ(leaf->enters, 3);
}

TEST(Retry, fails_after_num_attempts_failures) {
  ScriptedLeaf* leaf;
  auto retry = decorate<RetryNode>(&leaf, {F}, 2);
  EXPECT_EQ(retry->tick(), R);
  EXPECT_EQ(retry->tick(), F);
}

TEST(Retry, passes_running_through) {
  ScriptedLeaf* leaf;
  auto retry = decorate<RetryNode>(&leaf, {R}, 2);
  EXPECT_EQ(retry->tick(), R);
  EXPECT_EQ(leaf->enters, 1);
}

TEST(Timeout, halts_a_child_still_running_on_its_last_tick_and_fails) {
  ScriptedLeaf* leaf;
  auto timeout = decorate<TimeoutNode>(&leaf, {R}, 3L);
  EXPECT_EQ(timeout->tick(), R);
  EXPECT_EQ(timeout->tick(), R);
  EXPECT_EQ(timeout->tick(), F);
  EXPECT_EQ(leaf->halts, 1);
  EXPECT_EQ(timeout->tick(), R);  // a new run: the child is entered again with a fresh budget
  EXPECT_EQ(leaf->enters, 2);
}

TEST(Timeout, passes_success_and_failure_through_in_time) {
  ScriptedLeaf* leaf;
  auto timeout = decorate<TimeoutNode>(&leaf, {R, S}, 2L);
  EXPECT_EQ(timeout->tick(), R);
  EXPECT_EQ(timeout->tick(), S);
  EXPECT_EQ(leaf->halts, 0);
}

TEST(Decorators, halting_a_decorator_halts_its_running_child) {
  ScriptedLeaf* leaf;
  auto inverter = decorate<InverterNode>(&leaf, {R});
  inverter->tick();
  inverter->halt();
  EXPECT_EQ(leaf->halts, 1);
}

}  // namespace
}  // namespace roomba_rrt::bt
