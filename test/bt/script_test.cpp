// The script subset (script.h), the Script nodes, Precondition, SetBlackboard/UnsetBlackboard,
// and the pre/post-condition attributes (node_conditions.h), read from tree files as
// BehaviorTree.CPP writes them.
#include <gtest/gtest.h>

#include "roomba_rrt/bt/script.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, ScriptedLeaf

std::string sameName(const std::string& name) { return name; }

ScriptValue run(const std::string& code, Blackboard& board) {
  return Script(code, sameName).evaluate(board);
}

std::string syntaxError(const std::string& code) {
  try {
    Script(code, sameName);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

std::string evaluationError(const std::string& code, Blackboard& board) {
  try {
    run(code, board);
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Script, computes_with_bt_cpp_s_precedence) {
  Blackboard board;
  EXPECT_EQ(run("1 + 2 * 3", board), ScriptValue(7.0));
  EXPECT_EQ(run("(1 + 2) * 3 - -1", board), ScriptValue(10.0));
  EXPECT_EQ(run("7 / 2", board), ScriptValue(3.5));
  EXPECT_EQ(run("1 < 2 && 2 <= 2 || false", board), ScriptValue(true));
  EXPECT_EQ(run("!(3 >= 4) && 'a' != 'b' && 'a' == 'a'", board), ScriptValue(true));
  EXPECT_EQ(run("true == false", board), ScriptValue(false));
  EXPECT_EQ(run("2 > 1; 5", board), ScriptValue(5.0));  // the last statement's value
}

TEST(Script, assignments_create_and_write_keys_keeping_their_types) {
  Blackboard board;
  run("count := 1; count = count + 1; name := 'dock'; done := count == 2", board);
  EXPECT_EQ(*board.get<double>("count"), 2.0);
  EXPECT_EQ(*board.get<std::string>("name"), "dock");
  EXPECT_EQ(*board.get<bool>("done"), true);
  board.set<int>("laps", 3);
  run("laps = laps * 2", board);
  EXPECT_EQ(*board.get<int>("laps"), 6);
  EXPECT_EQ(evaluationError("laps = 0.5", board), "'laps' holds int, which cannot take 0.5");
  EXPECT_EQ(evaluationError("name = 3", board), "'name' holds string, not a number");
  EXPECT_EQ(evaluationError("missing = 1", board),
            "'missing' does not exist (create it with missing := ...)");
}

TEST(Script, what_cannot_be_evaluated_says_why) {
  Blackboard board;
  board.set<std::string>("mode", "clean");
  EXPECT_EQ(evaluationError("battery < 10", board), "'battery' was never written");
  board.declare<double>("battery");  // declared, never written
  EXPECT_EQ(evaluationError("battery < 10", board), "'battery' was never written");
  EXPECT_EQ(evaluationError("mode + 1", board), "arithmetic needs numbers, got 'clean'");
  EXPECT_EQ(evaluationError("mode == 1", board), "cannot compare 'clean' with 1");
  EXPECT_EQ(evaluationError("1 / 0", board), "division by zero");
  EXPECT_EQ(evaluationError("1e308 * 10", board), "a result out of range (1e+308, 10)");
  EXPECT_THROW(Script("mode", sameName).isTrue(board), ScriptError);
  board.set<std::vector<int>>("list", {});
  EXPECT_EQ(evaluationError("list", board).find("'list' holds "), 0u);
}

TEST(Script, syntax_errors_name_the_column) {
  EXPECT_EQ(syntaxError("a := (1 + 2"), "script 'a := (1 + 2': expected ')' at column 12");
  EXPECT_EQ(syntaxError("a b"), "script 'a b': expected ';' or the end at column 3");
  EXPECT_EQ(syntaxError("'open"), "script ''open': a string without its closing quote at column 1");
  EXPECT_EQ(syntaxError("1 +"), "script '1 +': expected a value at column 4");
  EXPECT_EQ(syntaxError(" ; "), "the script is empty");
  EXPECT_EQ(syntaxError("x := 1e999"), "script 'x := 1e999': a number out of range at column 6");
  EXPECT_EQ(syntaxError("a $ 1"), "script 'a $ 1': expected ';' or the end at column 3");
  // Parsing and evaluating recurse: a hostile file cannot exhaust the stack.
  EXPECT_NE(syntaxError(std::string(100000, '(') + "1").find("nested deeper than 64 levels"),
            std::string::npos);
  EXPECT_NE(syntaxError(std::string(100000, '!') + "1").find("nested deeper than 64 levels"),
            std::string::npos);
  std::string sum = "1";
  for (int i = 0; i < 100000; ++i) sum += "+1";
  EXPECT_NE(syntaxError(sum).find("more than 1000 operands and operators"), std::string::npos);
}

class ScriptedTree : public ::testing::Test {
 protected:
  ScriptedTree() {
    factory.registerLeaf("Work", [this](const NodeSpec& s) {
      return scripted(&work, {R, S}, s.name);
    });
    factory.registerLeaf("Fail", [](const NodeSpec& s) {
      return std::make_unique<ScriptedLeaf>(s.name, std::vector<Status>{F});
    });
  }
  Tree build(const std::string& body) {
    return factory.buildFromText(
        "<root BTCPP_format=\"4\"><BehaviorTree>\n" + body + "\n</BehaviorTree></root>", "t.xml",
        board);
  }
  std::string errorOf(const std::string& body) {
    try {
      build(body);
    } catch (const TreeFileError& e) {
      return e.what();
    }
    return "no error";
  }

  TreeFactory factory;
  std::shared_ptr<Blackboard> board = std::make_shared<Blackboard>();
  ScriptedLeaf* work = nullptr;
};

TEST_F(ScriptedTree, script_and_script_condition_read_and_write_the_blackboard) {
  Tree tree = build(R"(<Sequence>
    <Script code="docked := false"/>
    <ScriptCondition code="battery &gt; 10 &amp;&amp; !docked"/>
    <Script code="battery = battery - 10"/>
  </Sequence>)");
  board->set<double>("battery", 25);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(*board->get<double>("battery"), 15.0);
  EXPECT_EQ(*board->get<bool>("docked"), false);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(tree.tick(), F);  // 5 is not > 10
  EXPECT_EQ(*board->get<double>("battery"), 5.0);
}

TEST_F(ScriptedTree, a_script_that_cannot_run_fails_its_node) {
  Tree tree =
      build("<Fallback><Script code=\"n = 1\"/><Script code=\"failed := true\"/></Fallback>");
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(*board->get<bool>("failed"), true);
}

TEST_F(ScriptedTree, precondition_checks_once_per_run_and_returns_else_when_false) {
  board->set<double>("battery", 50);
  Tree tree = build(R"(<Precondition if="battery &gt; 20" else="SUCCESS"><Work/></Precondition>)");
  EXPECT_EQ(tree.tick(), R);
  board->set<double>("battery", 10);  // not re-checked while the child runs
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(work->ticks, 2);
  EXPECT_EQ(tree.tick(), S);  // a new run: false, `else` without ticking the child
  EXPECT_EQ(work->ticks, 2);
  EXPECT_EQ(errorOf("<Precondition if=\"1\" else=\"IDLE\"><Work/></Precondition>"),
            "t.xml:2: <Precondition>: port 'else' must be SUCCESS, FAILURE, RUNNING or SKIPPED, "
            "got 'IDLE'");
}

TEST_F(ScriptedTree, set_and_unset_blackboard_write_copy_and_forget_keys) {
  board->set<double>("speed", 0.2);
  board->set<int>("laps", 0);
  Tree tree = build(R"(<Sequence>
    <SetBlackboard value="0.5" output_key="speed"/>
    <SetBlackboard value="3" output_key="{laps}"/>
    <SetBlackboard value="hello" output_key="greeting"/>
    <SetBlackboard value="{speed}" output_key="copy"/>
    <UnsetBlackboard key="greeting"/>
  </Sequence>)");
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(*board->get<double>("speed"), 0.5);
  EXPECT_EQ(*board->get<int>("laps"), 3);
  EXPECT_EQ(*board->get<double>("copy"), 0.5);
  EXPECT_EQ(board->get<std::string>("greeting"), nullptr);
  EXPECT_EQ(errorOf("<SetBlackboard output_key=\"speed\"/>"),
            "t.xml:2: <SetBlackboard>: missing port 'value'");
  Tree refused = build("<SetBlackboard value=\"fast\" output_key=\"speed\"/>");
  EXPECT_EQ(refused.tick(), F);  // not a number: the double is left alone
  EXPECT_EQ(*board->get<double>("speed"), 0.5);
}

TEST_F(ScriptedTree, failure_if_and_success_if_decide_without_ticking_when_not_running) {
  board->set<bool>("blocked", false);
  board->set<bool>("done", false);
  Tree tree = build("<Work _failureIf=\"blocked\" _successIf=\"done\"/>");
  EXPECT_EQ(tree.tick(), R);
  board->set<bool>("blocked", true);  // not checked while it runs
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(tree.tick(), F);  // a new run: blocked
  board->set<bool>("blocked", false);
  board->set<bool>("done", true);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(work->ticks, 2);
  EXPECT_EQ(work->enters, 1);
}

TEST_F(ScriptedTree, post_conditions_run_by_outcome_and_on_halt) {
  Tree tree = build(R"(<ReactiveSequence>
    <ScriptCondition code="go"/>
    <Work _onSuccess="result := 'ok'" _onFailure="result := 'failed'" _post="runs := runs + 1"
          _onHalted="result := 'halted'"/>
  </ReactiveSequence>)");
  board->set<bool>("go", true);
  board->set<double>("runs", 0);
  EXPECT_EQ(tree.tick(), R);
  EXPECT_EQ(board->get<std::string>("result"), nullptr);
  board->set<bool>("go", false);
  EXPECT_EQ(tree.tick(), F);  // the condition halts Work
  EXPECT_EQ(*board->get<std::string>("result"), "halted");
  EXPECT_EQ(*board->get<double>("runs"), 0.0);
  board->set<bool>("go", true);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(*board->get<std::string>("result"), "ok");
  EXPECT_EQ(*board->get<double>("runs"), 1.0);
  Tree failing = build("<Fail _onFailure=\"result = 'failed'\" _post=\"runs = runs + 1\"/>");
  EXPECT_EQ(failing.tick(), F);
  EXPECT_EQ(*board->get<std::string>("result"), "failed");
  EXPECT_EQ(*board->get<double>("runs"), 2.0);
}

TEST_F(ScriptedTree, a_condition_that_cannot_run_fails_the_node) {
  Tree tree = build("<Work _successIf=\"never_written\"/>");
  EXPECT_EQ(tree.tick(), F);
  EXPECT_EQ(work->ticks, 0);
  Tree post = build("<AlwaysSuccess _post=\"x = 1\"/>");
  EXPECT_EQ(post.tick(), F);
}

TEST_F(ScriptedTree, script_variables_follow_the_subtree_s_remapping) {
  Tree tree = factory.buildFromText(R"(<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main"><Sequence>
    <SubTree ID="Count" n="{laps}"/><SubTree ID="Count" n="{laps}"/>
  </Sequence></BehaviorTree>
  <BehaviorTree ID="Count"><Script code="n = n + 1; private := 1"/></BehaviorTree>
</root>)",
                                    "t.xml", board);
  board->set<double>("laps", 0);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(*board->get<double>("laps"), 2.0);
  EXPECT_EQ(board->get<double>("private"), nullptr);  // private to each SubTree instance
  EXPECT_EQ(*board->get<double>("Count#1/private"), 1.0);
}

TEST_F(ScriptedTree, conditions_on_a_subtree_guard_its_root_in_the_caller_s_scope) {
  Tree tree = factory.buildFromText(R"(<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main">
    <SubTree ID="Job" _successIf="done" _onSuccess="done := true"/>
  </BehaviorTree>
  <BehaviorTree ID="Job"><Work/></BehaviorTree>
</root>)",
                                    "t.xml", board);
  board->set<bool>("done", false);
  EXPECT_EQ(tree.tick(), R);
  EXPECT_EQ(tree.tick(), S);
  EXPECT_EQ(*board->get<bool>("done"), true);  // the caller's key, not Job#1/done
  EXPECT_EQ(tree.tick(), S);                   // _successIf: Work not ticked again
  EXPECT_EQ(work->ticks, 2);
  try {
    factory.buildFromText(R"(<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main"><SubTree ID="Twice" _skipIf="true"/></BehaviorTree>
  <BehaviorTree ID="Twice"><Work _skipIf="false"/></BehaviorTree></root>)",
                          "t.xml");
    FAIL() << "conditions in two places were accepted";
  } catch (const TreeFileError& e) {
    EXPECT_STREQ(e.what(),
                 "t.xml:2: <SubTree>: both this SubTree and the root of tree \"Twice\" have "
                 "pre/post-conditions: keep them in one place");
  }
}

TEST_F(ScriptedTree, bad_scripts_and_unknown_conditions_are_refused_naming_the_element) {
  EXPECT_EQ(errorOf("<Script code=\"a :=\"/>"),
            "t.xml:2: <Script>: script 'a :=': expected a value at column 5");
  EXPECT_EQ(errorOf("<Work _successIf=\"1 +\"/>"),
            "t.xml:2: <Work>: attribute '_successIf': script '1 +': expected a value at column 4");
  EXPECT_EQ(errorOf("<Work _unknown=\"true\"/>"), "t.xml:2: <Work>: unknown attribute '_unknown'");
}

}  // namespace
}  // namespace roomba_rrt::bt
