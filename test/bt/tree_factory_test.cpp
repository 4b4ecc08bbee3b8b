// Trees from XML: the lab's tree builds, and invalid files name the element and the line.
#include <gtest/gtest.h>

#include <string>

#include "roomba_rrt/behavior/roomba_tree.h"
#include "roomba_rrt/bt/selector_node.h"
#include "roomba_rrt/bt/tree_factory.h"

namespace roomba_rrt::bt {
namespace {

/// A factory with two trivial leaves: Ok (SUCCESS) and Busy (RUNNING).
class TreeFactoryTest : public ::testing::Test {
 protected:
  TreeFactoryTest() {
    factory.registerLeaf(
        "Ok", [](const NodeSpec& s) { return std::make_unique<Fixed>(s.name, Status::kSuccess); });
    factory.registerLeaf("Busy", [](const NodeSpec& s) {
      return std::make_unique<Fixed>(s.name, Status::kRunning);
    });
  }

  /// The message of the TreeFileError that building `body` (inside <BehaviorTree>) throws.
  std::string errorOf(const std::string& body) {
    try {
      factory.buildFromText("<root>\n<BehaviorTree>\n" + body + "\n</BehaviorTree>\n</root>",
                            "test.xml");
    } catch (const TreeFileError& e) {
      return e.what();
    }
    return "no error";
  }

  struct Fixed final : LeafNode {
    Fixed(std::string name, Status status) : LeafNode(std::move(name)), status(status) {}
    Status onTick() override { return status; }
    Status status;
  };

  TreeFactory factory;
};

TEST_F(TreeFactoryTest, builds_composites_and_decorators_from_xml) {
  Tree tree = factory.buildFromText(R"(<root><BehaviorTree>
      <Sequence name="top"> <Ok/> <Inverter><Ok/></Inverter> </Sequence>
    </BehaviorTree></root>)");
  EXPECT_EQ(tree.root().name(), "top");
  EXPECT_EQ(tree.tick(), Status::kFailure);
}

TEST_F(TreeFactoryTest, picks_the_main_tree_to_execute) {
  Tree tree = factory.buildFromText(R"(<root main_tree_to_execute="B">
      <BehaviorTree ID="A"><Ok/></BehaviorTree>
      <BehaviorTree ID="B"><Busy/></BehaviorTree></root>)");
  EXPECT_EQ(tree.tick(), Status::kRunning);
}

TEST_F(TreeFactoryTest, decorator_attributes_are_read) {
  Tree tree = factory.buildFromText(
      R"(<root><BehaviorTree><Timeout ticks="2"><Busy/></Timeout></BehaviorTree></root>)");
  EXPECT_EQ(tree.tick(), Status::kRunning);
  EXPECT_EQ(tree.tick(), Status::kFailure);
}

TEST_F(TreeFactoryTest, an_unknown_node_is_named_with_its_line) {
  EXPECT_EQ(errorOf("<Sequence>\n<Ok/>\n<Jump/>\n</Sequence>"),
            "test.xml:5: <Jump>: unknown node type");
}

TEST_F(TreeFactoryTest, a_leaf_with_children_is_rejected) {
  EXPECT_EQ(errorOf("<Ok>\n<Ok/>\n</Ok>"), "test.xml:3: <Ok>: a leaf cannot have children");
}

TEST_F(TreeFactoryTest, an_empty_composite_is_rejected) {
  EXPECT_EQ(errorOf("<Selector>\n</Selector>"),
            "test.xml:3: <Selector>: a control node needs at least one child");
}

TEST_F(TreeFactoryTest, a_decorator_needs_exactly_one_child) {
  EXPECT_EQ(errorOf("<Inverter>\n<Ok/>\n<Ok/>\n</Inverter>"),
            "test.xml:3: <Inverter>: a decorator needs exactly one child, got 2");
}

TEST_F(TreeFactoryTest, bad_attributes_are_rejected) {
  EXPECT_EQ(errorOf("<Repeat cycles=\"3\"><Ok/></Repeat>"),
            "test.xml:3: <Repeat>: unknown attribute 'cycles'");
  EXPECT_EQ(errorOf("<Repeat num_cycles=\"three\"><Ok/></Repeat>"),
            "test.xml:3: <Repeat>: attribute 'num_cycles' must be an integer, got 'three'");
  EXPECT_EQ(errorOf("<Timeout ticks=\"-1\"><Ok/></Timeout>")
                .rfind("test.xml:3: <Timeout>: attribute 'ticks' must be in [0, ", 0),
            0u);
  EXPECT_EQ(errorOf("<Timeout><Ok/></Timeout>"),
            "test.xml:3: <Timeout>: give either msec (BehaviorTree.CPP v4) or ticks, not neither");
  EXPECT_EQ(errorOf("<Timeout msec=\"100\" ticks=\"2\"><Ok/></Timeout>"),
            "test.xml:3: <Timeout>: give either msec (BehaviorTree.CPP v4) or ticks, not both");
}

TEST_F(TreeFactoryTest, a_value_the_node_itself_refuses_names_the_element_and_the_field) {
  EXPECT_EQ(errorOf("<Repeat num_cycles=\"0\"><Ok/></Repeat>"),
            "test.xml:3: <Repeat>: num_cycles: must be >= 1 or -1 (forever), got 0");
  try {
    factory.buildFromText(
        "<root><BehaviorTree><Retry num_attempts=\"0\"><Ok/></Retry>"
        "</BehaviorTree></root>",
        "t.xml");
    FAIL() << "accepted num_attempts 0";
  } catch (const util::InvalidInput& e) {  // TreeFileError is one: element, line, problem
    EXPECT_EQ(e.field(), "<Retry>");
    EXPECT_EQ(e.source(), "t.xml:1");
    EXPECT_EQ(e.problem(), "num_attempts: must be >= 1 or -1 (unlimited), got 0");
  }
}

TEST_F(TreeFactoryTest, malformed_xml_names_the_line) {
  const std::string message = errorOf("<Sequence>\n<Ok>\n</Sequence>");
  EXPECT_EQ(message.rfind("test.xml:", 0), 0u) << message;
  EXPECT_NE(message.find("malformed XML"), std::string::npos) << message;
}

TEST_F(TreeFactoryTest, a_missing_behavior_tree_is_rejected) {
  EXPECT_THROW(factory.buildFromText("<root/>"), TreeFileError);
  EXPECT_THROW(factory.buildFromText("<tree><BehaviorTree><Ok/></BehaviorTree></tree>"),
               TreeFileError);
  EXPECT_THROW(factory.buildFromFile("/nonexistent/tree.xml"), TreeFileError);
}

TEST(RoombaTreeFile, the_config_file_is_the_lab_tree) {
  behavior::RoombaParams params;
  behavior::RoombaContext context(1);
  TreeFactory factory;
  behavior::registerRoombaLeaves(factory, params, context);
  Tree tree = factory.buildFromFile(ROOMBA_RRT_CONFIG_DIR "/roomba_tree.xml");
  auto* root = dynamic_cast<SelectorNode*>(&tree.root());
  ASSERT_NE(root, nullptr);
  ASSERT_EQ(root->childCount(), 2u);
  EXPECT_EQ(root->child(0).name(), "clean");
  EXPECT_EQ(root->child(1).name(), "recover");
}

}  // namespace
}  // namespace roomba_rrt::bt
