// TreeMonitor: every node's status as BehaviorTree.CPP's monitors (Groot2) show it, and the tree
// as Groot2's 'T' reply carries it.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "roomba_rrt/bt/tree_factory.h"
#include "roomba_rrt/bt/tree_monitor.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

using namespace testing;  // NOLINT: S, F, R, ScriptedLeaf
using M = MonitorStatus;

/// A tree of scripted leaves A, B and C (their scripts given) built from a tree file's body.
struct Fixture {
  Fixture(const std::string& body, std::vector<Status> a, std::vector<Status> b = {S},
          std::vector<Status> c = {S}) {
    const auto leaf = [](ScriptedLeaf** out, std::vector<Status> script) {
      return [out, script](const NodeSpec& spec) { return scripted(out, script, spec.name); };
    };
    factory.registerLeaf("A", leaf(&leaf_a, std::move(a)));
    factory.registerLeaf("B", leaf(&leaf_b, std::move(b)));
    factory.registerLeaf("C", leaf(&leaf_c, std::move(c)));
    tree = std::make_unique<Tree>(factory.buildFromText(
        "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\">" + body + "</BehaviorTree></root>"));
    monitor = std::make_unique<TreeMonitor>(tree->root());
  }
  /// Ticks the tree, updates the monitor, and gives every node's status.
  std::vector<M> tick() {
    tree->tick();
    monitor->update();
    return monitor->statuses();
  }

  TreeFactory factory;
  ScriptedLeaf *leaf_a = nullptr, *leaf_b = nullptr, *leaf_c = nullptr;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<TreeMonitor> monitor;
};

const char* kCleanTree =
    R"(<Fallback name="top"><Sequence name="clean"><A/><B name="spiral"/></Sequence><C/></Fallback>)";

TEST(TreeMonitor, numbers_nodes_from_1_in_preorder_with_their_type_name_and_path) {
  Fixture f(kCleanTree, {S});
  const auto& nodes = f.monitor->nodes();
  ASSERT_EQ(nodes.size(), 5u);
  const std::vector<std::string> types{"Fallback", "Sequence", "A", "B", "C"};
  const std::vector<std::string> paths{"top", "top/clean", "top/clean/A", "top/clean/spiral",
                                       "top/C"};
  const std::vector<int> parents{-1, 0, 1, 1, 0};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_EQ(nodes[i].uid, i + 1);
    EXPECT_EQ(nodes[i].type, types[i]);
    EXPECT_EQ(nodes[i].path, paths[i]);
    EXPECT_EQ(nodes[i].parent, parents[i]);
  }
  EXPECT_EQ(nodes[3].name, "spiral");
  EXPECT_EQ(nodes[1].end, 4);  // clean's descendants are nodes 2 and 3
}

TEST(TreeMonitor, legacy_spellings_show_their_v4_type) {
  TreeFactory factory;
  factory.setNoticeHandler({});
  factory.registerLeaf("A", [](const NodeSpec& s) {
    ScriptedLeaf* leaf = nullptr;
    return scripted(&leaf, {S}, s.name);
  });
  Tree tree =
      factory.buildFromText("<root><BehaviorTree><Selector><A/></Selector></BehaviorTree></root>");
  EXPECT_EQ(TreeMonitor(tree.root()).nodes()[0].type, "Fallback");
}

TEST(TreeMonitor, nodes_never_ticked_are_idle) {
  Fixture f(kCleanTree, {R});
  EXPECT_FALSE(f.monitor->update());
  EXPECT_EQ(f.tick(), (std::vector<M>{M::kRunning, M::kRunning, M::kRunning, M::kIdle, M::kIdle}));
}

TEST(TreeMonitor, a_finished_child_shows_its_result_while_its_parent_runs) {
  Fixture f(kCleanTree, {S}, {R});
  EXPECT_EQ(f.tick(),
            (std::vector<M>{M::kRunning, M::kRunning, M::kSuccess, M::kRunning, M::kIdle}));
}

TEST(TreeMonitor, when_a_parent_finishes_its_children_go_idle_and_the_root_keeps_its_result) {
  Fixture f(kCleanTree, {S}, {R, F}, {F});
  f.tick();
  // spiral fails: clean fails, C fails, the root fails; BT.CPP resets every child.
  EXPECT_EQ(f.tick(), (std::vector<M>{M::kFailure, M::kIdleFromFailure, M::kIdleFromSuccess,
                                      M::kIdleFromFailure, M::kIdleFromFailure}));
}

TEST(TreeMonitor, a_child_finished_in_an_earlier_run_stays_idle_when_its_parent_starts_again) {
  Fixture f(kCleanTree, {S, R}, {S});
  f.tick();  // everything succeeds
  EXPECT_EQ(f.tick(),
            (std::vector<M>{M::kRunning, M::kRunning, M::kRunning, M::kIdleFromSuccess, M::kIdle}));
}

TEST(TreeMonitor, halted_nodes_are_idle_from_running) {
  Fixture f(kCleanTree, {R});
  f.tick();
  f.tree->halt();
  EXPECT_TRUE(f.monitor->update());
  EXPECT_EQ(f.monitor->statuses(), (std::vector<M>{M::kIdleFromRunning, M::kIdleFromRunning,
                                                   M::kIdleFromRunning, M::kIdle, M::kIdle}));
}

TEST(TreeMonitor, update_says_whether_a_status_changed) {
  Fixture f(kCleanTree, {R, R, S}, {R});
  f.tree->tick();
  EXPECT_TRUE(f.monitor->update());
  f.tree->tick();
  EXPECT_FALSE(f.monitor->update());  // A still running
  f.tree->tick();
  EXPECT_TRUE(f.monitor->update());  // A succeeded, B runs
}

TEST(TreeXmlWithUids, nests_every_node_with_its_uid_and_adds_the_model) {
  Fixture f(kCleanTree, {S});
  const std::string model =
      R"(<root BTCPP_format="4"><TreeNodesModel><Action ID="A"/></TreeNodesModel></root>)";
  const std::string xml = treeXmlWithUids(*f.monitor, "Main", model);
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS) << xml;
  const tinyxml2::XMLElement* root = doc.FirstChildElement("root");
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Attribute("BTCPP_format"), "4");
  const tinyxml2::XMLElement* tree = root->FirstChildElement("BehaviorTree");
  ASSERT_NE(tree, nullptr);
  EXPECT_STREQ(tree->Attribute("ID"), "Main");
  const tinyxml2::XMLElement* top = tree->FirstChildElement("Fallback");
  ASSERT_NE(top, nullptr);
  EXPECT_STREQ(top->Attribute("name"), "top");
  EXPECT_EQ(top->IntAttribute("_uid"), 1);
  const tinyxml2::XMLElement* spiral = top->FirstChildElement("Sequence")->LastChildElement();
  EXPECT_STREQ(spiral->Name(), "B");
  EXPECT_STREQ(spiral->Attribute("name"), "spiral");
  EXPECT_EQ(spiral->IntAttribute("_uid"), 4);
  EXPECT_EQ(top->LastChildElement()->IntAttribute("_uid"), 5);
  const tinyxml2::XMLElement* nodes_model = root->FirstChildElement("TreeNodesModel");
  ASSERT_NE(nodes_model, nullptr);
  EXPECT_STREQ(nodes_model->FirstChildElement("Action")->Attribute("ID"), "A");
}

TEST(TreeColumns, leaves_side_by_side_and_parents_centred_over_their_children) {
  Fixture f(kCleanTree, {S});
  // top(clean(A, spiral), C)
  EXPECT_EQ(treeColumns(*f.monitor), (std::vector<double>{1.25, 0.5, 0, 1, 2}));
}

TEST(MainTreeId, is_main_tree_to_execute_or_the_only_tree) {
  EXPECT_EQ(mainTreeId(R"(<root main_tree_to_execute="B"><BehaviorTree ID="A"/></root>)"), "B");
  EXPECT_EQ(mainTreeId(R"(<root><BehaviorTree ID="Roomba"/></root>)"), "Roomba");
  EXPECT_EQ(mainTreeId(R"(<root><BehaviorTree/></root>)"), "MainTree");
  EXPECT_EQ(mainTreeId("not xml"), "MainTree");
}

}  // namespace
}  // namespace roomba_rrt::bt
