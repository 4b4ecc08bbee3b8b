// Tree files in BehaviorTree.CPP v4's format: its node names and ports, SequenceWithMemory,
// SubTree with remapping, <include>, v3 spellings with a notice, and the TreeNodesModel that
// Groot2 reads.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/sequence_with_memory.h"
#include "roomba_rrt/bt/timeout_node.h"
#include "roomba_rrt/bt/tree_factory.h"

namespace roomba_rrt::bt {
namespace {

/// A leaf that returns the statuses it is given, one per tick (the last one forever), and counts
/// its ticks.
struct Scripted final : LeafNode {
  Scripted(std::string name, std::vector<Status> script)
      : LeafNode(std::move(name)), script(std::move(script)) {}
  Status onTick() override {
    const Status s = script[std::min(ticks, script.size() - 1)];
    ++ticks;
    return s;
  }
  std::vector<Status> script;
  std::size_t ticks = 0;
};

/// Writes `text` to key `out` (Say text="..." out="{key}") and succeeds.
struct Say final : LeafNode {
  static PortList providedPorts() {
    return {inputPort<std::string>("text", "what to write"),
            outputPort<std::string>("out", "where to write it", "{said}")};
  }
  Say(std::string name, InputPort<std::string> text, OutputPort<std::string> out)
      : LeafNode(std::move(name)), text(std::move(text)), out(std::move(out)) {}
  Status onTick() override {
    out.set(*text.get());
    return Status::kSuccess;
  }
  InputPort<std::string> text;
  OutputPort<std::string> out;
};

/// Adds one to key `n`, which it reads and writes (an inout port).
struct Count final : LeafNode {
  static PortList providedPorts() { return {inoutPort<int>("n", "the count")}; }
  Count(std::string name, OutputPort<int> n) : LeafNode(std::move(name)), n(n) {}
  Status onTick() override {
    n.set(n.get() ? *n.get() + 1 : 1);
    return Status::kSuccess;
  }
  OutputPort<int> n;
};

struct IsSunny final : ConditionNode {
  using ConditionNode::ConditionNode;
  static PortList providedPorts() { return {}; }
  Status onTick() override { return Status::kSuccess; }
};

class TreeFileFormat : public ::testing::Test {
 protected:
  TreeFileFormat() {
    factory.setNoticeHandler([this](const std::string& text) { notices.push_back(text); });
    factory.registerLeaf("Ok", [](const NodeSpec& s) {
      return std::make_unique<Scripted>(s.name, std::vector<Status>{Status::kSuccess});
    });
    factory.registerNodeType<Say>("Say", [](const NodeSpec& s) {
      return std::make_unique<Say>(s.name, s.input<std::string>("text"),
                                   s.output<std::string>("out"));
    });
    factory.registerNodeType<Count>("Count", [](const NodeSpec& s) {
      return std::make_unique<Count>(s.name, s.output<int>("n"));
    });
    factory.registerNodeType<IsSunny>(
        "IsSunny", [](const NodeSpec& s) { return std::make_unique<IsSunny>(s.name); });
  }

  std::string errorOf(const std::string& xml, const std::string& source = "t.xml") {
    try {
      factory.buildFromText(xml, source);
    } catch (const TreeFileError& e) {
      return e.what();
    }
    return "no error";
  }

  /// A file in the test's scratch directory, removed at the end.
  std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    files.push_back(path);
    return path;
  }
  ~TreeFileFormat() override {
    for (const auto& f : files) std::remove(f.c_str());
  }

  TreeFactory factory;
  std::vector<std::string> notices;
  std::vector<std::string> files;
};

TEST(SequenceWithMemoryNode, resumes_at_the_child_that_failed_not_at_the_first) {
  SequenceWithMemory seq("seq");
  auto first = std::make_unique<Scripted>("first", std::vector<Status>{Status::kSuccess});
  auto second = std::make_unique<Scripted>(
      "second", std::vector<Status>{Status::kFailure, Status::kRunning, Status::kSuccess});
  Scripted* a = first.get();
  Scripted* b = second.get();
  seq.addChild(std::move(first));
  seq.addChild(std::move(second));
  EXPECT_EQ(seq.tick(), Status::kFailure);
  EXPECT_EQ(seq.tick(), Status::kRunning);  // `second` again: `first` is not re-ticked
  EXPECT_EQ(a->ticks, 1u);
  seq.halt();  // halting keeps the place, as BehaviorTree.CPP v4 does
  EXPECT_EQ(seq.tick(), Status::kSuccess);
  EXPECT_EQ(a->ticks, 1u);
  EXPECT_EQ(b->ticks, 3u);
  EXPECT_EQ(seq.tick(), Status::kSuccess);  // after success it starts from the first child
  EXPECT_EQ(a->ticks, 2u);
}

TEST_F(TreeFileFormat, reads_what_behavior_tree_cpp_v4_writes_without_notices) {
  Tree tree = factory.buildFromText(R"(
<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main">
    <Fallback>
      <ReactiveFallback><IsSunny/></ReactiveFallback>
      <ReactiveSequence><Ok/></ReactiveSequence>
      <SequenceWithMemory><Ok/></SequenceWithMemory>
      <Sequence>
        <Inverter><Ok/></Inverter>
        <Repeat num_cycles="2"><Ok/></Repeat>
        <RetryUntilSuccessful num_attempts="3"><Ok/></RetryUntilSuccessful>
        <Timeout msec="500"><Ok/></Timeout>
      </Sequence>
    </Fallback>
  </BehaviorTree>
  <TreeNodesModel><Action ID="Ok"/></TreeNodesModel>
</root>)",
                                    "v4.xml");
  EXPECT_EQ(tree.tick(), Status::kSuccess);
  EXPECT_TRUE(notices.empty()) << notices.front();
}

// What Groot 1 writes, and BehaviorTree.CPP v4 still reads: the category element with an ID.
TEST_F(TreeFileFormat, the_explicit_form_is_read_as_the_node_its_id_names) {
  const std::string file = writeFile("bt_groot1.xml", R"(
<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main">
    <Control ID="Sequence" name="both">
      <Condition ID="IsSunny"/>
      <Decorator ID="Inverter"><Decorator ID="Inverter"><Action ID="Ok"/></Decorator></Decorator>
      <Action ID="Say" text="hi" out="{said}"/>
      <SubTree ID="Other"/>
    </Control>
  </BehaviorTree>
  <BehaviorTree ID="Other"><Action ID="Ok"/></BehaviorTree>
</root>)");
  Tree tree = factory.buildFromFile(file);
  EXPECT_EQ(tree.tick(), Status::kSuccess);
  EXPECT_EQ(*tree.blackboard().get<std::string>("said"), "hi");
  EXPECT_EQ(tree.root().name(), "both");
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(factory.typesUsedIn(file),
            (std::set<std::string>{"Inverter", "IsSunny", "Ok", "Say", "Sequence"}));
}

TEST_F(TreeFileFormat, the_explicit_form_needs_a_known_id) {
  EXPECT_EQ(errorOf("<root BTCPP_format=\"4\">\n<BehaviorTree>\n<Action/>\n</BehaviorTree></root>"),
            "t.xml:3: <Action>: needs an ID attribute naming the node type");
  EXPECT_EQ(errorOf("<root BTCPP_format=\"4\">\n<BehaviorTree>\n<Action ID=\"Fly\"/>\n"
                    "</BehaviorTree></root>"),
            "t.xml:3: <Action>: unknown node type 'Fly'");
  EXPECT_EQ(errorOf("<root BTCPP_format=\"4\"><BehaviorTree>\n<Action ID=\"Say\" text=\"a\" "
                    "colour=\"red\"/>\n</BehaviorTree></root>"),
            "t.xml:2: <Action>: unknown attribute 'colour'");
}

TEST_F(TreeFileFormat, v3_spellings_are_read_with_a_notice_naming_the_v4_one) {
  Tree tree = factory.buildFromText(
      "<root>\n<BehaviorTree>\n<Selector>\n<RetryUntilSuccesful num_attempts=\"2\"><Ok/>"
      "</RetryUntilSuccesful>\n<SequenceStar><Ok/></SequenceStar>\n</Selector>\n"
      "</BehaviorTree>\n</root>",
      "old.xml");
  EXPECT_EQ(tree.tick(), Status::kSuccess);
  ASSERT_EQ(notices.size(), 3u);
  EXPECT_EQ(notices[0],
            "old.xml:3: <Selector> is read as <Fallback>, its BehaviorTree.CPP v4 "
            "name: write that");
  EXPECT_NE(notices[1].find("old.xml:4: <RetryUntilSuccesful> is read as <RetryUntilSuccessful>"),
            std::string::npos);
  EXPECT_NE(notices[2].find("<SequenceStar> is read as <SequenceWithMemory>"), std::string::npos);
}

TEST_F(TreeFileFormat, timeout_in_milliseconds_counts_ticks_at_the_tick_rate) {
  factory.registerLeaf("Busy", [](const NodeSpec& s) {
    return std::make_unique<Scripted>(s.name, std::vector<Status>{Status::kRunning});
  });
  factory.setTickRate(10);  // 250 ms = 2.5 ticks: rounded to 3 (nearest), never 0
  Tree tree = factory.buildFromText(
      R"(<root BTCPP_format="4"><BehaviorTree><Timeout msec="250"><Busy/></Timeout>
         </BehaviorTree></root>)");
  EXPECT_EQ(tree.tick(), Status::kRunning);
  EXPECT_EQ(tree.tick(), Status::kRunning);
  EXPECT_EQ(tree.tick(), Status::kFailure);
  EXPECT_EQ(TimeoutNode::ticksFor(1, 10), 1);
  EXPECT_EQ(TimeoutNode::ticksFor(1000, 60), 60);
}

TEST_F(TreeFileFormat, unknown_things_are_still_refused_naming_element_and_line) {
  EXPECT_EQ(
      errorOf("<root BTCPP_format=\"4\">\n<BehaviorTree>\n<Concurrently><Ok/></Concurrently>\n"
              "</BehaviorTree>\n</root>"),
      "t.xml:3: <Concurrently>: unknown node type");
  EXPECT_EQ(errorOf("<root BTCPP_format=\"5\"><BehaviorTree><Ok/></BehaviorTree></root>"),
            "t.xml:1: <root>: BTCPP_format \"5\" is not supported (4 or 3)");
  EXPECT_EQ(errorOf("<root>\n<Tree><Ok/></Tree>\n</root>"),
            "t.xml:2: <Tree>: unknown element under <root> (BehaviorTree, include or "
            "TreeNodesModel)");
}

// BehaviorTree.CPP's isolation: a SubTree's keys are its own unless remapped or autoremapped.
TEST_F(TreeFileFormat, sub_tree_keys_are_remapped_autoremapped_or_private) {
  auto board = std::make_shared<Blackboard>();
  board->declare<std::string>("greeting");  // the application writes it
  Tree tree = factory.buildFromText(R"(
<root BTCPP_format="4" main_tree_to_execute="Main">
  <BehaviorTree ID="Main">
    <Sequence>
      <SubTree ID="Greet" greeting="hello" said="{remapped}"/>
      <SubTree ID="Greet" greeting="{=}" _autoremap="true"/>
      <SubTree ID="Greet" greeting="private"/>
      <Say text="{said}" out="{echo}"/>
    </Sequence>
  </BehaviorTree>
  <BehaviorTree ID="Greet">
    <Say text="{greeting}" out="{said}"/>
  </BehaviorTree>
</root>)",
                                    "sub.xml", board);
  board->set<std::string>("greeting", "hi from the parent");
  ASSERT_EQ(tree.tick(), Status::kSuccess);
  EXPECT_EQ(*board->get<std::string>("remapped"), "hello");  // literal in, key remapped out
  EXPECT_EQ(*board->get<std::string>("said"), "hi from the parent");  // autoremapped both ways
  EXPECT_EQ(*board->get<std::string>("echo"), "hi from the parent");
  // The third instance wrote its own, private key.
  EXPECT_EQ(*board->get<std::string>("Greet#3/said"), "private");
}

TEST_F(TreeFileFormat, a_sub_tree_reading_a_private_key_nothing_writes_is_refused) {
  EXPECT_EQ(errorOf(R"(<root BTCPP_format="4" main_tree_to_execute="Main">
<BehaviorTree ID="Main"><SubTree ID="Greet"/></BehaviorTree>
<BehaviorTree ID="Greet">
<Say text="{greeting}"/>
</BehaviorTree></root>)"),
            "t.xml:4: <Say>: port 'text' reads blackboard key 'Greet#1/greeting', which nothing "
            "writes (no output port of the tree names it and the application did not declare "
            "it)");
}

TEST_F(TreeFileFormat, bad_sub_trees_are_refused) {
  const std::string head = "<root BTCPP_format=\"4\" main_tree_to_execute=\"A\">\n";
  EXPECT_EQ(errorOf(head + "<BehaviorTree ID=\"A\">\n<SubTree ID=\"B\"/>\n</BehaviorTree></root>"),
            "t.xml:3: <SubTree>: no <BehaviorTree ID=\"B\">");
  EXPECT_EQ(errorOf(head + "<BehaviorTree ID=\"A\">\n<SubTree/>\n</BehaviorTree></root>"),
            "t.xml:3: <SubTree>: needs an ID attribute naming a <BehaviorTree>");
  EXPECT_EQ(errorOf(head + "<BehaviorTree ID=\"A\"><SubTree ID=\"B\"/></BehaviorTree>\n"
                           "<BehaviorTree ID=\"B\">\n<SubTree ID=\"A\"/>\n</BehaviorTree></root>"),
            "t.xml:4: <SubTree>: the tree contains itself (A -> B -> A)");
  EXPECT_EQ(errorOf(head + "<BehaviorTree ID=\"A\">\n<SubTree ID=\"B\" _autoremap=\"yes\"/>\n"
                           "</BehaviorTree><BehaviorTree ID=\"B\"><Ok/></BehaviorTree></root>"),
            "t.xml:3: <SubTree>: attribute '_autoremap' must be true or false, got 'yes'");
}

TEST_F(TreeFileFormat, includes_are_read_relative_to_the_including_file) {
  writeFile("bt_included.xml", R"(<root BTCPP_format="4">
  <BehaviorTree ID="Greet"><Say text="{greeting}" out="{said}"/></BehaviorTree>
</root>)");
  const std::string main =
      writeFile("bt_main.xml", R"(<root BTCPP_format="4" main_tree_to_execute="Main">
  <include path="bt_included.xml"/>
  <BehaviorTree ID="Main"><SubTree ID="Greet" greeting="included" said="{out}"/></BehaviorTree>
</root>)");
  auto board = std::make_shared<Blackboard>();
  Tree tree = factory.buildFromFile(main, board);
  ASSERT_EQ(tree.tick(), Status::kSuccess);
  EXPECT_EQ(*board->get<std::string>("out"), "included");
  EXPECT_EQ(factory.typesUsedIn(main), (std::set<std::string>{"Say"}));
}

TEST_F(TreeFileFormat, an_include_that_is_missing_or_includes_itself_is_refused) {
  const std::string missing = writeFile("bt_missing.xml",
                                        "<root>\n<include path=\"nope.xml\"/>\n"
                                        "<BehaviorTree><Ok/></BehaviorTree>"
                                        "</root>");
  try {
    factory.buildFromFile(missing);
    FAIL() << "included a missing file";
  } catch (const TreeFileError& e) {
    EXPECT_NE(
        std::string(e.what()).find("bt_missing.xml:2: <include>: cannot include \"nope.xml\": "),
        std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("(no such file)"), std::string::npos);
  }
  const std::string device = writeFile("bt_device.xml",
                                       "<root>\n<include path=\"/dev/zero\"/>\n"
                                       "<BehaviorTree><Ok/></BehaviorTree></root>");
  try {
    factory.buildFromFile(device);  // never reads forever
    FAIL() << "included a device";
  } catch (const TreeFileError& e) {
    EXPECT_NE(std::string(e.what()).find("(not a regular file)"), std::string::npos) << e.what();
  }
  const std::string loop = writeFile("bt_loop.xml",
                                     "<root>\n<include path=\"bt_loop.xml\"/>\n"
                                     "<BehaviorTree><Ok/></BehaviorTree></root>");
  try {
    factory.buildFromFile(loop);
    FAIL() << "a file that includes itself was read";
  } catch (const TreeFileError& e) {
    EXPECT_NE(std::string(e.what()).find("the file includes itself"), std::string::npos)
        << e.what();
  }
}

TEST_F(TreeFileFormat, a_missing_tree_file_says_why) {
  try {
    factory.buildFromFile("/nonexistent/nope.xml");
    FAIL();
  } catch (const TreeFileError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/nope.xml:0: cannot read the tree file (no such file)");
  }
}

TEST_F(TreeFileFormat, the_tree_nodes_model_lists_our_nodes_with_their_ports_for_groot2) {
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(factory.treeNodesModel().c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* root = doc.RootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Attribute("BTCPP_format"), "4");
  const tinyxml2::XMLElement* model = root->FirstChildElement("TreeNodesModel");
  ASSERT_NE(model, nullptr);
  std::map<std::string, const tinyxml2::XMLElement*> nodes;
  for (const auto* e = model->FirstChildElement(); e; e = e->NextSiblingElement()) {
    nodes[e->Attribute("ID")] = e;
  }
  // Ours and Nav2's are listed; BehaviorTree.CPP's own (Sequence, Timeout, ...) are not.
  EXPECT_EQ(nodes.count("Sequence"), 0u);
  EXPECT_EQ(nodes.count("Timeout"), 0u);
  ASSERT_EQ(nodes.count("Say"), 1u);
  EXPECT_STREQ(nodes["Say"]->Name(), "Action");
  EXPECT_STREQ(nodes["IsSunny"]->Name(), "Condition");
  EXPECT_STREQ(nodes["RecoveryNode"]->Name(), "Control");
  EXPECT_STREQ(nodes["RateController"]->Name(), "Decorator");
  const auto* text = nodes["Say"]->FirstChildElement("input_port");
  ASSERT_NE(text, nullptr);
  EXPECT_STREQ(text->Attribute("name"), "text");
  EXPECT_STREQ(text->Attribute("type"), "string");
  EXPECT_STREQ(text->GetText(), "what to write");
  const auto* out = nodes["Say"]->FirstChildElement("output_port");
  ASSERT_NE(out, nullptr);
  EXPECT_STREQ(out->Attribute("default"), "{said}");
  const auto* inout = nodes["Count"]->FirstChildElement("inout_port");
  ASSERT_NE(inout, nullptr);
  EXPECT_STREQ(inout->Attribute("name"), "n");
}

TEST_F(TreeFileFormat, an_inout_port_needs_a_key_and_both_reads_and_writes_it) {
  Tree tree = factory.buildFromText(R"(<root BTCPP_format="4"><BehaviorTree>
    <Sequence><Count n="{n}"/><Count n="{n}"/></Sequence></BehaviorTree></root>)");
  EXPECT_EQ(tree.tick(), Status::kSuccess);
  EXPECT_EQ(*tree.blackboard().get<int>("n"), 2);
  EXPECT_EQ(errorOf("<root BTCPP_format=\"4\"><BehaviorTree>\n<Count n=\"3\"/>\n"
                    "</BehaviorTree></root>"),
            "t.xml:2: <Count>: inout port 'n' (int: the count) needs a blackboard key like {n}, "
            "got '3'");
}

}  // namespace
}  // namespace roomba_rrt::bt
