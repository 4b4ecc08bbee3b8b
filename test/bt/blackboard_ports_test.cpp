// Ports and the blackboard: tree files bind ports to literals or keys, and every mistake is
// refused when the tree is built, naming the element and its line. Also the tree-file limits
// (depth, node count, integer ranges, duplicate IDs).
#include <gtest/gtest.h>

#include <string>

#include "roomba_rrt/bt/tree_factory.h"

namespace roomba_rrt::bt {
namespace {

/// Writes `value` (a literal or key) to `out` and succeeds; FAILURE when `value` is unset.
class Copy final : public LeafNode {
 public:
  static PortList providedPorts() {
    return {inputPort<double>("value", "what to copy").range(-10, 10),
            outputPort<double>("out", "where to copy it")};
  }
  Copy(const NodeSpec& spec)
      : LeafNode(spec.name), in_(spec.input<double>("value")), out_(spec.output<double>("out")) {}

 private:
  Status onTick() override {
    const double* v = in_.get();
    if (!v) return Status::kFailure;
    out_.set(*v);
    return Status::kSuccess;
  }
  InputPort<double> in_;
  OutputPort<double> out_;
};

/// Reads an int port with a default.
class Count final : public LeafNode {
 public:
  static PortList providedPorts() { return {inputPort<int>("n", "how many", "3")}; }
  explicit Count(const NodeSpec& spec) : LeafNode(spec.name), n(spec.input<int>("n")) {}
  Status onTick() override { return *n.get() == 3 ? Status::kSuccess : Status::kFailure; }
  InputPort<int> n;
};

/// Reads a string key.
class Say final : public LeafNode {
 public:
  static PortList providedPorts() { return {inputPort<std::string>("text", "what to say")}; }
  explicit Say(const NodeSpec& spec) : LeafNode(spec.name) {
    (void)spec.input<std::string>("text");
  }
  Status onTick() override { return Status::kSuccess; }
};

class PortsTest : public ::testing::Test {
 protected:
  PortsTest() {
    factory.registerNodeType<Copy>("Copy",
                                   [](const NodeSpec& s) { return std::make_unique<Copy>(s); });
    factory.registerNodeType<Count>("Count",
                                    [](const NodeSpec& s) { return std::make_unique<Count>(s); });
    factory.registerNodeType<Say>("Say",
                                  [](const NodeSpec& s) { return std::make_unique<Say>(s); });
    factory.registerLeaf("Ok", [](const NodeSpec& s) { return std::make_unique<Count>(s); });
  }

  static std::string wrap(const std::string& body) {
    return "<root>\n<BehaviorTree>\n" + body + "\n</BehaviorTree>\n</root>";
  }
  std::string errorOf(const std::string& body,
                      std::shared_ptr<Blackboard> board = std::make_shared<Blackboard>()) {
    try {
      factory.buildFromText(wrap(body), "t.xml", board);
    } catch (const TreeFileError& e) {
      return e.what();
    }
    return "no error";
  }

  TreeFactory factory;
};

TEST_F(PortsTest, literals_and_keys_flow_through_the_blackboard) {
  Tree tree = factory.buildFromText(wrap(R"(<Sequence>
      <Copy value="2.5" out="{a}"/>
      <Copy value="{a}" out="{b}"/>
    </Sequence>)"));
  EXPECT_EQ(tree.blackboard().get<double>("b"), nullptr);  // nothing ran yet
  EXPECT_EQ(tree.tick(), Status::kSuccess);
  ASSERT_NE(tree.blackboard().get<double>("b"), nullptr);
  EXPECT_EQ(*tree.blackboard().get<double>("b"), 2.5);
}

TEST_F(PortsTest, the_application_declares_and_writes_keys_between_ticks) {
  auto board = std::make_shared<Blackboard>();
  auto& input = board->declare<double>("input");
  Tree tree = factory.buildFromText(wrap(R"(<Copy value="{input}" out="{out}"/>)"), "t", board);
  EXPECT_EQ(tree.tick(), Status::kFailure);  // declared, not yet written: the leaf sees nothing
  input.set(-4);
  EXPECT_EQ(tree.tick(), Status::kSuccess);
  EXPECT_EQ(*board->get<double>("out"), -4);
}

TEST_F(PortsTest, a_default_fills_a_left_out_port) {
  Tree tree = factory.buildFromText(wrap("<Count/>"));
  EXPECT_EQ(tree.tick(), Status::kSuccess);
}

TEST_F(PortsTest, a_missing_required_port_is_named) {
  EXPECT_EQ(errorOf(R"(<Copy value="1"/>)"),
            "t.xml:3: <Copy>: missing required port 'out' (double: where to copy it)");
}

TEST_F(PortsTest, a_literal_of_the_wrong_type_or_range_is_named) {
  EXPECT_EQ(errorOf(R"(<Copy value="one" out="{a}"/>)"),
            "t.xml:3: <Copy>: attribute 'value' must be a number, got 'one'");
  EXPECT_EQ(errorOf(R"(<Copy value="11" out="{a}"/>)"),
            "t.xml:3: <Copy>: attribute 'value' must be in [-10, 10], got 11");
  EXPECT_EQ(errorOf(R"(<Copy value="nan" out="{a}"/>)"),
            "t.xml:3: <Copy>: attribute 'value' must be finite, got nan");
  EXPECT_EQ(errorOf(R"(<Count n="3.5"/>)"),
            "t.xml:3: <Count>: attribute 'n' must be an integer, got '3.5'");
}

TEST_F(PortsTest, an_output_needs_a_key) {
  EXPECT_EQ(errorOf(R"(<Copy value="1" out="a"/>)"),
            "t.xml:3: <Copy>: output port 'out' (double: where to copy it) needs a blackboard key "
            "like {out}, got 'a'");
}

TEST_F(PortsTest, a_key_read_before_anything_writes_it_is_named) {
  EXPECT_EQ(errorOf("<Sequence>\n<Copy value=\"1\" out=\"{a}\"/>\n<Copy value=\"{b}\" "
                    "out=\"{c}\"/>\n</Sequence>"),
            "t.xml:5: <Copy>: port 'value' reads blackboard key 'b', which nothing writes (no "
            "output port of the tree names it and the application did not declare it)");
}

TEST_F(PortsTest, a_key_written_later_in_the_tree_may_be_read_earlier) {
  // A loop: the value of the previous tick (the reader handles "not yet written").
  EXPECT_EQ(errorOf("<Sequence>\n<Copy value=\"{a}\" out=\"{b}\"/>\n<Copy value=\"1\" "
                    "out=\"{a}\"/>\n</Sequence>"),
            "no error");
}

TEST_F(PortsTest, a_type_mismatch_between_two_ports_is_named) {
  EXPECT_EQ(
      errorOf("<Sequence>\n<Copy value=\"1\" out=\"{a}\"/>\n<Say text=\"{a}\"/>\n</Sequence>"),
      "t.xml:5: <Say>: port 'text' (string: what to say): blackboard key 'a' holds double, "
      "not string");
}

TEST_F(PortsTest, a_type_mismatch_with_the_application_is_named) {
  auto board = std::make_shared<Blackboard>();
  board->set<int>("a", 1);
  EXPECT_EQ(errorOf(R"(<Copy value="{a}" out="{b}"/>)", board),
            "t.xml:3: <Copy>: port 'value' (double: what to copy): blackboard key 'a' holds int, "
            "not double");
}

TEST_F(PortsTest, the_factory_lists_the_ports_of_a_type) {
  const PortList& ports = factory.ports("Copy");
  ASSERT_EQ(ports.size(), 2u);
  EXPECT_EQ(ports[0].name, "value");
  EXPECT_EQ(ports[0].type_name, "double");
  EXPECT_TRUE(ports[0].required());
  EXPECT_EQ(ports[1].direction, PortDirection::kOutput);
  EXPECT_EQ(factory.ports("RateController")[0].default_value, "1.0");
}

TEST(Blackboard, keeps_a_key_s_type) {
  Blackboard board;
  board.set<double>("x", 1.0);
  EXPECT_THROW(board.declare<int>("x"), std::invalid_argument);
  EXPECT_THROW(board.get<int>("x"), std::invalid_argument);
  EXPECT_EQ(board.get<double>("missing"), nullptr);
  board.declare<double>("x").clear();
  EXPECT_EQ(board.get<double>("x"), nullptr);
}

// Tree-file limits (issue 11): integers out of range, duplicate IDs, depth and size.
class TreeFileLimits : public PortsTest {};

TEST_F(TreeFileLimits, integers_out_of_their_type_are_refused_not_wrapped) {
  EXPECT_EQ(errorOf(R"(<Repeat num_cycles="4294967295"><Count/></Repeat>)"),
            "t.xml:3: <Repeat>: attribute 'num_cycles' must be an integer in [-2147483648, "
            "2147483647], got 4294967295");
  EXPECT_EQ(errorOf(R"(<Repeat num_cycles="-2147483649"><Count/></Repeat>)"),
            "t.xml:3: <Repeat>: attribute 'num_cycles' must be an integer in [-2147483648, "
            "2147483647], got -2147483649");
  EXPECT_EQ(errorOf(R"(<Retry num_attempts="-5"><Count/></Retry>)"),
            "t.xml:3: <Retry>: attribute 'num_attempts' must be in [-1, 2147483647], got -5");
  EXPECT_EQ(errorOf(R"(<Timeout ticks="99999999999999999999"><Count/></Timeout>)")
                .rfind("t.xml:3: <Timeout>: attribute 'ticks' must be an integer in [", 0),
            0u);
  EXPECT_EQ(errorOf(R"(<RateController hz="0"><Count/></RateController>)"),
            "t.xml:3: <RateController>: attribute 'hz' must be in [0.000001, 1000], got 0");
  EXPECT_EQ(errorOf(R"(<RecoveryNode number_of_retries="-1"><Count/><Count/></RecoveryNode>)"),
            "t.xml:3: <RecoveryNode>: attribute 'number_of_retries' must be in [0, 2147483647], "
            "got -1");
}

TEST_F(TreeFileLimits, a_recovery_node_needs_exactly_two_children) {
  EXPECT_EQ(errorOf("<RecoveryNode><Count/></RecoveryNode>"),
            "t.xml:3: <RecoveryNode>: needs exactly 2 children, got 1");
}

TEST_F(TreeFileLimits, two_behavior_trees_with_the_same_id_are_refused) {
  try {
    factory.buildFromText(
        "<root main_tree_to_execute=\"A\">\n<BehaviorTree ID=\"A\"><Count/>"
        "</BehaviorTree>\n<BehaviorTree ID=\"A\"><Count/></BehaviorTree>\n"
        "</root>",
        "t.xml");
    FAIL() << "accepted";
  } catch (const TreeFileError& e) {
    EXPECT_STREQ(e.what(), "t.xml:3: <BehaviorTree>: ID \"A\" is used twice (first on line 2)");
  }
}

TEST_F(TreeFileLimits, nesting_deeper_than_the_limit_is_refused) {
  std::string deep;
  for (int i = 0; i < TreeFactory::kMaxDepth; ++i) deep += "<Inverter>";
  std::string body = deep + "<Count/>";
  for (int i = 0; i < TreeFactory::kMaxDepth; ++i) body += "</Inverter>";
  const std::string message = errorOf(body);
  EXPECT_EQ(message, "t.xml:3: <Count>: nesting deeper than 64 nodes is not supported");
  // One level less builds.
  EXPECT_EQ(errorOf(deep.substr(10) + "<Count/>" + body.substr(body.size() - 11 * 63)), "no error");
}

TEST_F(TreeFileLimits, more_nodes_than_the_limit_are_refused) {
  std::string body = "<Sequence>";
  for (int i = 0; i < TreeFactory::kMaxNodes; ++i) body += "<Count/>";
  body += "</Sequence>";
  EXPECT_EQ(errorOf(body), "t.xml:3: <Count>: more than 10000 nodes in one tree is not supported");
}

}  // namespace
}  // namespace roomba_rrt::bt
