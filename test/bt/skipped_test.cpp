// BehaviorTree.CPP 4's SKIPPED status: what each composite and decorator does with a skipped
// child, RunOnce, Precondition's else, and the _skipIf and _while conditions that produce it.
#include <gtest/gtest.h>

#include "roomba_rrt/bt/force_status.h"
#include "roomba_rrt/bt/inverter_node.h"
#include "roomba_rrt/bt/keep_running_until_failure.h"
#include "roomba_rrt/bt/parallel_all_node.h"
#include "roomba_rrt/bt/parallel_node.h"
#include "roomba_rrt/bt/pipeline_sequence.h"
#include "roomba_rrt/bt/reactive_selector.h"
#include "roomba_rrt/bt/reactive_sequence.h"
#include "roomba_rrt/bt/recovery_node.h"
#include "roomba_rrt/bt/repeat_node.h"
#include "roomba_rrt/bt/retry_node.h"
#include "roomba_rrt/bt/run_once_node.h"
#include "roomba_rrt/bt/selector_node.h"
#include "roomba_rrt/bt/sequence_node.h"
#include "roomba_rrt/bt/sequence_with_memory.h"
#include "roomba_rrt/bt/timeout_node.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, K, ScriptedLeaf

TEST(Skipped, sequences_go_past_a_skipped_child_and_are_skipped_when_all_were) {
  TwoChildren<SequenceNode> seq({K}, {S});
  EXPECT_EQ(seq.node.tick(), S);
  EXPECT_EQ(seq.second->ticks, 1);
  TwoChildren<SequenceNode> all({K}, {K});
  EXPECT_EQ(all.node.tick(), K);
  EXPECT_FALSE(all.node.isRunning());
  TwoChildren<SequenceWithMemory> memory({K}, {R, K});
  EXPECT_EQ(memory.node.tick(), R);
  EXPECT_EQ(memory.node.tick(), S);  // the second child ran (RUNNING) in this run
  TwoChildren<ReactiveSequence> reactive({K}, {K});
  EXPECT_EQ(reactive.node.tick(), K);
  TwoChildren<PipelineSequence> pipeline({K}, {S});
  EXPECT_EQ(pipeline.node.tick(), S);
}

TEST(Skipped, fallbacks_go_past_a_skipped_child_and_are_skipped_when_all_were) {
  TwoChildren<SelectorNode> fallback({K}, {F});
  EXPECT_EQ(fallback.node.tick(), F);
  TwoChildren<SelectorNode> all({K}, {K});
  EXPECT_EQ(all.node.tick(), K);
  TwoChildren<ReactiveSelector> reactive({K}, {S});
  EXPECT_EQ(reactive.node.tick(), S);
  TwoChildren<ReactiveSelector> reactive_all({K}, {K});
  EXPECT_EQ(reactive_all.node.tick(), K);
}

TEST(Skipped, parallels_count_a_skipped_child_as_done) {
  TwoChildren<ParallelNode, int, int> parallel({K}, {R, S}, -1, 1);
  EXPECT_EQ(parallel.node.tick(), R);
  EXPECT_EQ(parallel.node.tick(), S);  // "all" succeeded: the skipped one counts
  TwoChildren<ParallelNode, int, int> all_skipped({K}, {K}, -1, 1);
  EXPECT_EQ(all_skipped.node.tick(), S);  // as in BT.CPP: "all" reached by skipped ones
  TwoChildren<ParallelNode, int, int> none_counted({K}, {K}, 1, 1);
  EXPECT_EQ(none_counted.node.tick(), K);
  TwoChildren<ParallelAllNode, int> parallel_all({K}, {S}, 1);
  EXPECT_EQ(parallel_all.node.tick(), S);
}

TEST(Skipped, decorators_pass_it_through_but_keep_running_keeps_running) {
  ScriptedLeaf* leaf;
  EXPECT_EQ(decorate<InverterNode>(&leaf, {K})->tick(), K);
  EXPECT_EQ(decorate<ForceSuccess>(&leaf, {K})->tick(), K);
  EXPECT_EQ(decorate<RepeatNode>(&leaf, {K}, 3)->tick(), K);
  EXPECT_EQ(decorate<RetryNode>(&leaf, {K}, 3)->tick(), K);
  EXPECT_EQ(decorate<TimeoutNode>(&leaf, {K}, 3L)->tick(), K);
  EXPECT_EQ(decorate<KeepRunningUntilFailure>(&leaf, {K})->tick(), R);
  RecoveryNode recovery("recovery", 1);
  recovery.addChild(scripted(&leaf, {K}));
  recovery.addChild(std::make_unique<ScriptedLeaf>("recover", std::vector<Status>{S}));
  EXPECT_EQ(recovery.tick(), K);
}

TEST(Skipped, run_once_runs_the_child_to_its_end_once_then_skips_or_repeats_its_status) {
  ScriptedLeaf* leaf;
  auto once = decorate<RunOnceNode>(&leaf, {R, F, S}, true);
  EXPECT_EQ(once->tick(), R);
  EXPECT_EQ(once->tick(), F);
  EXPECT_EQ(once->tick(), K);
  EXPECT_EQ(leaf->ticks, 2);
  auto same = decorate<RunOnceNode>(&leaf, {R, F, S}, false);
  same->tick();
  same->halt();  // a halt before it finished does not count
  EXPECT_EQ(same->tick(), F);
  EXPECT_EQ(same->tick(), F);
  EXPECT_EQ(leaf->ticks, 2);
}

class SkipConditions : public ::testing::Test {
 protected:
  SkipConditions() {
    factory.registerLeaf("Work",
                         [this](const NodeSpec& s) { return scripted(&work, {R}, s.name); });
  }
  Tree build(const std::string& body) {
    return factory.buildFromText(
        "<root BTCPP_format=\"4\"><BehaviorTree>" + body + "</BehaviorTree></root>", "t.xml",
        board);
  }
  TreeFactory factory;
  std::shared_ptr<Blackboard> board = std::make_shared<Blackboard>();
  ScriptedLeaf* work = nullptr;
};

TEST_F(SkipConditions, skip_if_skips_a_node_that_is_not_running) {
  board->set<bool>("docked", true);
  Tree tree = build("<Sequence><Work _skipIf=\"docked\"/><AlwaysSuccess/></Sequence>");
  EXPECT_EQ(tree.tick(), S);  // Work skipped, the Sequence goes on
  EXPECT_EQ(work->ticks, 0);
  board->set<bool>("docked", false);
  EXPECT_EQ(tree.tick(), R);
  board->set<bool>("docked", true);  // not checked while it runs
  EXPECT_EQ(tree.tick(), R);
  EXPECT_EQ(work->ticks, 2);
}

TEST_F(SkipConditions, while_is_checked_every_tick_and_halts_the_node_when_false) {
  board->set<bool>("charged", true);
  Tree tree = build(
      "<Fallback><Work _while=\"charged\" _onHalted=\"stopped := true\"/><AlwaysFailure/>"
      "</Fallback>");
  EXPECT_EQ(tree.tick(), R);
  board->set<bool>("charged", false);
  EXPECT_EQ(tree.tick(), F);  // Work halted and skipped; the Fallback goes on
  EXPECT_EQ(work->halts, 1);
  EXPECT_EQ(*board->get<bool>("stopped"), true);
  EXPECT_EQ(tree.tick(), F);
  EXPECT_EQ(work->ticks, 1);
}

TEST_F(SkipConditions, precondition_may_return_skipped) {
  Tree tree = build("<Precondition if=\"false\" else=\"SKIPPED\"><Work/></Precondition>");
  EXPECT_EQ(tree.tick(), K);
  EXPECT_EQ(work->ticks, 0);
}

}  // namespace
}  // namespace roomba_rrt::bt
