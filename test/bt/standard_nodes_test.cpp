// BehaviorTree.CPP 4's standard nodes beyond the ones our trees were first written with:
// AlwaysSuccess/Failure, ForceSuccess/Failure, KeepRunningUntilFailure, Delay, Sleep, Parallel,
// ParallelAll, IfThenElse, WhileDoElse, Switch, LoopInt/Double/String/Bool. One test per line of
// their header contracts, and each read from a tree file with BT.CPP's ports.
#include <gtest/gtest.h>

#include "roomba_rrt/bt/always_status.h"
#include "roomba_rrt/bt/delay_node.h"
#include "roomba_rrt/bt/entry_updated.h"
#include "roomba_rrt/bt/force_status.h"
#include "roomba_rrt/bt/if_then_else_node.h"
#include "roomba_rrt/bt/keep_running_until_failure.h"
#include "roomba_rrt/bt/loop_node.h"
#include "roomba_rrt/bt/parallel_all_node.h"
#include "roomba_rrt/bt/parallel_node.h"
#include "roomba_rrt/bt/selector_node.h"
#include "roomba_rrt/bt/sequence_node.h"
#include "roomba_rrt/bt/sleep_node.h"
#include "roomba_rrt/bt/switch_node.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "roomba_rrt/bt/try_catch_node.h"
#include "roomba_rrt/bt/while_do_else_node.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, ScriptedLeaf

/// `node` over scripted children reachable through `leaves`.
template <class Node, class... Args>
std::unique_ptr<Node> compose(std::vector<ScriptedLeaf**> leaves,
                              std::vector<std::vector<Status>> scripts, Args... args) {
  auto node = std::make_unique<Node>("node", args...);
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    node->addChild(scripted(leaves[i], scripts[i], "child" + std::to_string(i)));
  }
  return node;
}

TEST(AlwaysStatus, answers_its_status_every_tick) {
  AlwaysSuccess yes("yes");
  AlwaysFailure no("no");
  EXPECT_EQ(yes.tick(), S);
  EXPECT_EQ(yes.tick(), S);
  EXPECT_EQ(no.tick(), F);
  EXPECT_FALSE(no.isRunning());
}

TEST(ForceStatus, replaces_success_and_failure_and_keeps_running) {
  ScriptedLeaf* leaf;
  auto force_success = decorate<ForceSuccess>(&leaf, {F, S, R});
  EXPECT_EQ(force_success->tick(), S);
  EXPECT_EQ(force_success->tick(), S);
  EXPECT_EQ(force_success->tick(), R);
  auto force_failure = decorate<ForceFailure>(&leaf, {S, F, R});
  EXPECT_EQ(force_failure->tick(), F);
  EXPECT_EQ(force_failure->tick(), F);
  EXPECT_EQ(force_failure->tick(), R);
}

TEST(KeepRunningUntilFailure, success_restarts_the_child_on_the_next_tick) {
  ScriptedLeaf* leaf;
  auto keep = decorate<KeepRunningUntilFailure>(&leaf, {S, S, R, F});
  EXPECT_EQ(keep->tick(), R);
  EXPECT_EQ(keep->tick(), R);
  EXPECT_EQ(leaf->enters, 2);  // entered anew after each success, once per tick
  EXPECT_EQ(keep->tick(), R);
  EXPECT_EQ(keep->tick(), F);
  EXPECT_EQ(leaf->ticks, 4);
}

/// A node timed by the tree's clock, ticked the way Tree::tick() does.
struct Clocked {
  Status tick(TreeNode& node) {
    clock.advanceTick();
    return node.tick();
  }
  Blackboard clock;
};

TEST(Delay, waits_its_ticks_before_ticking_the_child) {
  Clocked c;
  ScriptedLeaf* leaf;
  auto delay = decorate<DelayNode>(&leaf, {R, S}, 2L, c.clock);
  EXPECT_EQ(c.tick(*delay), R);
  EXPECT_EQ(c.tick(*delay), R);
  EXPECT_EQ(leaf->ticks, 0);
  EXPECT_EQ(c.tick(*delay), R);  // two ticks after it was entered: the child runs
  EXPECT_EQ(c.tick(*delay), S);  // no further wait while the child runs
  EXPECT_EQ(leaf->ticks, 2);
  EXPECT_EQ(c.tick(*delay), R);  // finished: the next run waits again
  EXPECT_EQ(leaf->ticks, 2);
}

TEST(Delay, ticks_the_child_at_once_without_a_delay_and_returns_its_failure) {
  Clocked c;
  ScriptedLeaf* leaf;
  auto delay = decorate<DelayNode>(&leaf, {F}, 0L, c.clock);
  EXPECT_EQ(c.tick(*delay), F);
  EXPECT_THROW(DelayNode("d", -1, c.clock), std::invalid_argument);
}

TEST(Delay, halt_halts_the_child_and_the_next_tick_waits_again) {
  Clocked c;
  ScriptedLeaf* leaf;
  auto delay = decorate<DelayNode>(&leaf, {R}, 1L, c.clock);
  c.tick(*delay);
  EXPECT_EQ(c.tick(*delay), R);
  EXPECT_EQ(leaf->ticks, 1);
  delay->halt();
  EXPECT_EQ(leaf->halts, 1);
  EXPECT_EQ(c.tick(*delay), R);
  EXPECT_EQ(leaf->ticks, 1);
}

TEST(Sleep, runs_for_its_ticks_then_succeeds_and_starts_over) {
  Clocked c;
  SleepNode sleep("sleep", 2, c.clock);
  EXPECT_EQ(c.tick(sleep), R);
  EXPECT_EQ(c.tick(sleep), R);
  EXPECT_EQ(c.tick(sleep), S);
  EXPECT_EQ(c.tick(sleep), R);
  SleepNode no_sleep("none", 0, c.clock);
  EXPECT_EQ(c.tick(no_sleep), S);
}

TEST(Sleep, time_passes_while_it_is_not_ticked_and_a_halt_starts_it_over) {
  Clocked c;
  SleepNode sleep("sleep", 3, c.clock);
  EXPECT_EQ(c.tick(sleep), R);
  c.clock.advanceTick();  // ticks in which its parent did not tick it still count
  c.clock.advanceTick();
  EXPECT_EQ(c.tick(sleep), S);
  EXPECT_EQ(c.tick(sleep), R);
  sleep.halt();
  EXPECT_EQ(c.tick(sleep), R);
  EXPECT_EQ(c.tick(sleep), R);
}

TEST(Parallel, ticks_every_child_in_one_tick_and_succeeds_when_enough_succeed) {
  ScriptedLeaf *a, *b, *c;
  auto parallel = compose<ParallelNode>({&a, &b, &c}, {{S}, {R, S}, {R}}, 2, 1);
  EXPECT_EQ(parallel->tick(), R);
  EXPECT_EQ(a->ticks + b->ticks + c->ticks, 3);
  EXPECT_EQ(parallel->tick(), S);  // b's success is the second
  EXPECT_EQ(a->ticks, 1);          // finished children are not ticked again
  EXPECT_EQ(c->halts, 1);          // the running child is halted
}

TEST(Parallel, fails_at_the_failure_count_and_halts_the_others) {
  ScriptedLeaf *a, *b;
  auto parallel = compose<ParallelNode>({&a, &b}, {{R}, {R, F}}, -1, 1);
  EXPECT_EQ(parallel->tick(), R);
  EXPECT_EQ(parallel->tick(), F);
  EXPECT_EQ(a->halts, 1);
}

TEST(Parallel, fails_as_soon_as_the_success_count_cannot_be_reached) {
  ScriptedLeaf *a, *b, *c;
  auto parallel = compose<ParallelNode>({&a, &b, &c}, {{F}, {R}, {R}}, -1, 3);
  EXPECT_EQ(parallel->tick(), F);  // -1: all three must succeed; one failed
  EXPECT_EQ(b->ticks, 0);
}

TEST(Parallel, thresholds_beyond_the_children_are_refused) {
  EXPECT_EQ(ParallelNode("p", -1, 1).childCountProblem(2), "");
  EXPECT_EQ(ParallelNode("p", 3, 1).childCountProblem(2),
            "success_count=\"3\" asks for 3 children, not 1 to the 2 it has");
  EXPECT_EQ(ParallelNode("p", 1, -4).childCountProblem(2),
            "failure_count=\"-4\" asks for -1 children, not 1 to the 2 it has");
}

TEST(ParallelAll, waits_for_every_child_then_counts_the_failures) {
  ScriptedLeaf *a, *b, *c;
  auto all = compose<ParallelAllNode>({&a, &b, &c}, {{F}, {R, S}, {R, R, S}}, 2);
  EXPECT_EQ(all->tick(), R);
  EXPECT_EQ(all->tick(), R);  // one failure does not stop the others
  EXPECT_EQ(all->tick(), S);  // one failure < max_failures 2
  EXPECT_EQ(a->ticks, 1);
  auto failing = compose<ParallelAllNode>({&a, &b}, {{F}, {R, F}}, -1);
  EXPECT_EQ(failing->tick(), R);
  EXPECT_EQ(failing->tick(), F);  // -1: both failed
}

TEST(IfThenElse, the_condition_chooses_a_branch_that_runs_to_its_end) {
  ScriptedLeaf *cond, *then, *otherwise;
  auto node = compose<IfThenElseNode>({&cond, &then, &otherwise}, {{R, S, F}, {R, S}, {F}});
  EXPECT_EQ(node->tick(), R);  // the condition runs
  EXPECT_EQ(node->tick(), R);  // it succeeded: `then` ticked in the same tick
  EXPECT_EQ(node->tick(), S);  // `then` again, the condition not re-checked
  EXPECT_EQ(cond->ticks, 2);
  EXPECT_EQ(node->tick(), F);  // a new run: the condition fails, `else` fails
  EXPECT_EQ(otherwise->ticks, 1);
}

TEST(IfThenElse, without_an_else_a_failed_condition_fails) {
  ScriptedLeaf *cond, *then;
  auto node = compose<IfThenElseNode>({&cond, &then}, {{F}, {S}});
  EXPECT_EQ(node->tick(), F);
  EXPECT_EQ(then->ticks, 0);
  EXPECT_NE(node->childCountProblem(4), "");
}

TEST(WhileDoElse, rechecks_the_condition_and_halts_the_branch_it_leaves) {
  ScriptedLeaf *cond, *body, *otherwise;
  auto node = compose<WhileDoElseNode>({&cond, &body, &otherwise}, {{S, S, F, R}, {R}, {R}});
  EXPECT_EQ(node->tick(), R);
  EXPECT_EQ(node->tick(), R);
  EXPECT_EQ(cond->ticks, 2);
  EXPECT_EQ(node->tick(), R);  // the condition failed: `do` halted, `else` runs
  EXPECT_EQ(body->halts, 1);
  EXPECT_EQ(otherwise->ticks, 1);
  EXPECT_EQ(node->tick(), R);  // the condition runs: neither branch ticked nor halted
  EXPECT_EQ(otherwise->ticks, 1);
  EXPECT_EQ(otherwise->halts, 0);
}

TEST(WhileDoElse, without_an_else_a_failed_condition_fails_and_halts_do) {
  ScriptedLeaf *cond, *body;
  auto node = compose<WhileDoElseNode>({&cond, &body}, {{S, F}, {R}});
  EXPECT_EQ(node->tick(), R);
  EXPECT_EQ(node->tick(), F);
  EXPECT_EQ(body->halts, 1);
}

TEST(Switch, the_matching_case_runs_the_last_child_by_default_and_a_move_halts) {
  Blackboard board;
  auto& mode = board.declare<std::string>("mode");
  std::vector<InputPort<std::string>> cases = {InputPort<std::string>::literal("clean"),
                                               InputPort<std::string>::literal("2")};
  SwitchNode node("switch", InputPort<std::string>::key(mode), cases);
  ScriptedLeaf *clean, *two, *other;
  node.addChild(scripted(&clean, {R}));
  node.addChild(scripted(&two, {S}));
  node.addChild(scripted(&other, {F}));
  EXPECT_EQ(node.tick(), F);  // never written: the default
  mode.set("clean");
  EXPECT_EQ(node.tick(), R);
  mode.set("2.0");  // numbers match by value
  EXPECT_EQ(node.tick(), S);
  EXPECT_EQ(clean->halts, 1);
  EXPECT_EQ(two->ticks, 1);
}

TEST(EntryUpdated, reacts_to_writes_since_it_last_looked) {
  Blackboard board;
  auto& goal = board.declare<double>("goal");
  WasEntryUpdated updated("updated", "goal", board);
  EXPECT_EQ(updated.tick(), F);  // never written
  goal.set(1);
  EXPECT_EQ(updated.tick(), S);
  EXPECT_EQ(updated.tick(), F);
  ScriptedLeaf* leaf;
  auto skip = decorate<EntryUpdatedDecorator>(&leaf, {R, S}, "goal", board, Status::kSkipped);
  EXPECT_EQ(skip->tick(), R);  // written once before: that counts
  EXPECT_EQ(skip->tick(), S);  // a running child is ticked to its end
  EXPECT_EQ(skip->tick(), Status::kSkipped);
  goal.set(2);
  EXPECT_EQ(skip->tick(), S);
  auto wait = decorate<EntryUpdatedDecorator>(&leaf, {S}, "missing", board, R);
  EXPECT_EQ(wait->tick(), R);  // WaitValueUpdate: RUNNING until written
}

TEST(AsyncSequence, yields_after_a_child_that_finished_in_the_tick_it_was_entered) {
  auto seq = std::make_unique<SequenceNode>("async", true);
  ScriptedLeaf *a, *b, *c;
  seq->addChild(scripted(&a, {S}));
  seq->addChild(scripted(&b, {R, S}));
  seq->addChild(scripted(&c, {S}));
  EXPECT_EQ(seq->tick(), R);  // a succeeded at once: yield
  EXPECT_EQ(b->ticks, 0);
  EXPECT_EQ(seq->tick(), R);  // b runs
  EXPECT_EQ(seq->tick(), S);  // b had been running: c in the same tick, the last child
  auto fallback = std::make_unique<SelectorNode>("async", true);
  fallback->addChild(scripted(&a, {F}));
  fallback->addChild(scripted(&b, {S}));
  EXPECT_EQ(fallback->tick(), R);
  EXPECT_EQ(fallback->tick(), S);
}

TEST(TryCatch, a_failure_in_the_try_block_runs_the_catch_child_then_fails) {
  ScriptedLeaf *a, *b, *catcher;
  auto node = compose<TryCatchNode>({&a, &b, &catcher}, {{S}, {R, F, S}, {R, S}}, false);
  EXPECT_EQ(node->tick(), R);
  EXPECT_EQ(node->tick(), R);  // b failed: catch ticked in the same tick, running
  EXPECT_EQ(catcher->ticks, 1);
  EXPECT_EQ(node->tick(), F);  // catch finished: FAILURE whatever it returned
  EXPECT_EQ(node->tick(), S);  // a new run: the try block succeeds
  EXPECT_EQ(catcher->ticks, 2);
  EXPECT_NE(node->childCountProblem(1), "");
}

TEST(TryCatch, catch_on_halt_runs_the_catch_child_when_halted_in_the_try_block) {
  ScriptedLeaf *a, *catcher;
  auto node = compose<TryCatchNode>({&a, &catcher}, {{R}, {R}}, true);
  EXPECT_EQ(node->tick(), R);
  node->halt();
  EXPECT_EQ(a->halts, 1);
  EXPECT_EQ(catcher->ticks, 1);
  EXPECT_EQ(catcher->halts, 1);  // still running: stopped
}

/// A LoopInt over "2;5;7" whose child records the value it is given; `if_empty` as given.
struct LoopRun {
  explicit LoopRun(const std::string& queue, const std::string& if_empty = "SUCCESS",
                   Status child = Status::kSuccess)
      : tree(build(queue, if_empty, child)) {}

  /// Appends {v} at each tick and returns `child`.
  struct RecordValue final : LeafNode {
    RecordValue(std::string name, Blackboard& board, std::vector<int>& seen, Status child)
        : LeafNode(std::move(name)), board_(board), seen_(seen), child_(child) {}
    Status onTick() override {
      seen_.push_back(*board_.get<int>("v"));
      return child_;
    }
    Blackboard& board_;
    std::vector<int>& seen_;
    Status child_;
  };

  Tree build(const std::string& queue, const std::string& if_empty, Status child) {
    factory.registerLeaf("Record", [this, child](const NodeSpec& s) {
      return std::make_unique<RecordValue>(s.name, *board, seen, child);
    });
    return factory.buildFromText("<root BTCPP_format=\"4\"><BehaviorTree><LoopInt queue=\"" +
                                     queue + "\" if_empty=\"" + if_empty +
                                     "\" value=\"{v}\"><Record/></LoopInt></BehaviorTree></root>",
                                 "t", board);
  }

  TreeFactory factory;
  std::shared_ptr<Blackboard> board = std::make_shared<Blackboard>();
  std::vector<int> seen;
  Tree tree;
};

TEST(LoopNode, runs_the_child_once_per_value_then_returns_if_empty) {
  LoopRun run("2;5;7");
  EXPECT_EQ(run.tree.tick(), R);
  EXPECT_EQ(run.tree.tick(), R);
  EXPECT_EQ(run.tree.tick(), R);
  EXPECT_EQ(run.tree.tick(), S);  // no value left
  EXPECT_EQ(run.seen, (std::vector<int>{2, 5, 7}));
  EXPECT_EQ(run.tree.tick(), R);  // entered anew: the queue again
  EXPECT_EQ(run.seen.back(), 2);
}

TEST(LoopNode, an_empty_queue_returns_if_empty_without_ticking_the_child) {
  LoopRun skipped("", "SKIPPED");
  EXPECT_EQ(skipped.tree.tick(), Status::kSkipped);
  LoopRun failed("", "FAILURE");
  EXPECT_EQ(failed.tree.tick(), F);
  EXPECT_TRUE(failed.seen.empty());
}

TEST(LoopNode, a_failing_child_fails_the_loop) {
  LoopRun run("1;2", "SUCCESS", Status::kFailure);
  EXPECT_EQ(run.tree.tick(), F);
  EXPECT_EQ(run.seen, (std::vector<int>{1}));
}

TEST(LoopNode, a_queue_on_the_blackboard_is_read_not_emptied_and_bad_literals_are_refused) {
  TreeFactory factory;
  auto board = std::make_shared<Blackboard>();
  board->set<std::deque<double>>("q", {0.5, 1.5});
  Tree tree = factory.buildFromText(
      R"(<root BTCPP_format="4"><BehaviorTree><LoopDouble queue="{q}" value="{v}"><AlwaysSuccess/></LoopDouble></BehaviorTree></root>)",
      "t", board);
  EXPECT_EQ(tree.tick(), R);
  EXPECT_EQ(*board->get<double>("v"), 0.5);
  EXPECT_EQ(tree.tick(), R);
  EXPECT_EQ(*board->get<double>("v"), 1.5);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(board->get<std::deque<double>>("q")->size(), 2u);
  for (const char* bad :
       {R"(<LoopInt queue="1;x" value="{v}"><AlwaysSuccess/></LoopInt>)",
        R"(<LoopBool queue="true" if_empty="RUNNING" value="{b}"><AlwaysSuccess/></LoopBool>)"}) {
    EXPECT_THROW(factory.buildFromText(std::string("<root BTCPP_format=\"4\"><BehaviorTree>") +
                                       bad + "</BehaviorTree></root>"),
                 std::exception)
        << bad;
  }
}

/// The standard nodes as a tree file names them, with BT.CPP's ports.
TEST(StandardNodes, are_read_from_tree_files_with_behaviortree_cpp_s_ports) {
  TreeFactory factory;
  factory.setTickRate(10);  // Sleep 200 ms = 2 ticks
  factory.registerLeaf("Busy", [](const NodeSpec& s) {
    return std::make_unique<ScriptedLeaf>(s.name, std::vector<Status>{R});
  });
  Tree tree = factory.buildFromText(R"(
<root BTCPP_format="4"><BehaviorTree>
  <Sequence>
    <ForceSuccess><AlwaysFailure/></ForceSuccess>
    <Inverter><ForceFailure><AlwaysSuccess/></ForceFailure></Inverter>
    <IfThenElse><AlwaysSuccess/><Sleep msec="200"/><AlwaysFailure/></IfThenElse>
    <Parallel success_count="1" failure_count="2"><AlwaysSuccess/><Busy/></Parallel>
    <ParallelAll max_failures="2"><AlwaysFailure/><AlwaysSuccess/></ParallelAll>
    <WhileDoElse><AlwaysFailure/><Busy/><AlwaysSuccess/></WhileDoElse>
    <Switch2 variable="b" case_1="a" case_2="b"><Busy/><Delay delay_msec="0"><AlwaysSuccess/></Delay><Busy/></Switch2>
    <SetBlackboard value="1" output_key="mode"/>
    <WasEntryUpdated entry="{mode}"/>
    <SkipUnlessUpdated entry="mode"><AlwaysSuccess/></SkipUnlessUpdated>
    <WaitValueUpdate entry="mode"><AlwaysSuccess/></WaitValueUpdate>
    <TryCatch catch_on_halt="true"><AsyncSequence><AlwaysSuccess/></AsyncSequence><AlwaysSuccess/></TryCatch>
    <AsyncFallback><AlwaysSuccess/></AsyncFallback>
    <KeepRunningUntilFailure><AlwaysSuccess/></KeepRunningUntilFailure>
  </Sequence>
</BehaviorTree></root>)");
  EXPECT_EQ(tree.tick(), R);  // Sleep
  EXPECT_EQ(tree.tick(), R);
  EXPECT_EQ(tree.tick(), R);  // on to KeepRunningUntilFailure, which never ends
  EXPECT_EQ(tree.tick(), R);
}

TEST(StandardNodes, child_counts_their_ports_cannot_serve_are_refused) {
  TreeFactory factory;
  const auto error = [&](const std::string& body) {
    try {
      factory.buildFromText("<root BTCPP_format=\"4\"><BehaviorTree>\n" + body +
                            "\n</BehaviorTree></root>");
    } catch (const TreeFileError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("<Parallel success_count=\"3\"><AlwaysSuccess/><AlwaysSuccess/></Parallel>"),
            "<string>:2: <Parallel>: success_count=\"3\" asks for 3 children, not 1 to the 2 it "
            "has");
  EXPECT_EQ(error("<IfThenElse><AlwaysSuccess/></IfThenElse>"),
            "<string>:2: <IfThenElse>: needs 2 or 3 children (if, then, else), got 1");
  EXPECT_EQ(error("<Switch2 variable=\"a\" case_1=\"a\" case_2=\"b\"><AlwaysSuccess/>"
                  "<AlwaysSuccess/></Switch2>"),
            "<string>:2: <Switch2>: needs exactly 3 children, got 2");
  EXPECT_EQ(error("<Sleep/>"),
            "<string>:2: <Sleep>: missing required port 'msec' (long: milliseconds to wait)");
}

}  // namespace
}  // namespace roomba_rrt::bt
