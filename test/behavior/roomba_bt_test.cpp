// What is particular to the BT: the idle tick when the root completes, and trees from files.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/bt/tree_factory.h"

namespace roomba_rrt::behavior {
namespace {

const robot::BumperState kFree{};

/// Writes `xml` to a temporary file and returns its path.
std::string writeTree(const std::string& xml) {
  const std::string path = ::testing::TempDir() + "roomba_bt_test_tree.xml";
  std::ofstream(path) << xml;
  return path;
}

TEST(RoombaBt, the_tick_in_which_the_root_completes_commands_zero_and_keeps_the_leaf_name) {
  RoombaBt roomba(RoombaParams{}, 1);
  for (int i = 0; i < 180 + 1200; ++i) ASSERT_FALSE(roomba.tick(kFree).v == 0);
  const robot::Velocity idle = roomba.tick(kFree);  // MoveInSpiral's time is up: the root succeeds
  EXPECT_TRUE(roomba.lastTickIdle());
  EXPECT_EQ(idle.v, 0.0);
  EXPECT_EQ(idle.w, 0.0);
  EXPECT_EQ(roomba.stateName(), "MoveInSpiral");
  const robot::Velocity next = roomba.tick(kFree);  // the root starts again from the left
  EXPECT_FALSE(roomba.lastTickIdle());
  EXPECT_EQ(roomba.stateName(), "MoveForward");
  EXPECT_EQ(next.v, 0.5);
}

TEST(RoombaBt, a_tree_file_rearranges_the_behaviour_and_names_the_leaves) {
  const std::string path = writeTree(R"(<root><BehaviorTree>
      <Sequence><MoveInSpiral name="Swirl"/><MoveForward/></Sequence>
    </BehaviorTree></root>)");
  RoombaBt roomba(RoombaParams{}, 1, path);
  const robot::Velocity cmd = roomba.tick(kFree);
  EXPECT_EQ(roomba.stateName(), "Swirl");
  EXPECT_EQ(roomba.state(), RoombaState::kMoveInSpiral);
  EXPECT_DOUBLE_EQ(cmd.w, 0.5 / 0.2);
  std::remove(path.c_str());
}

TEST(RoombaBt, an_invalid_tree_file_names_the_element_and_the_line) {
  const std::string path = writeTree(
      "<root>\n<BehaviorTree>\n<Sequence>\n<Rotate>\n<GoBack/>\n</Rotate>\n</Sequence>\n"
      "</BehaviorTree>\n</root>\n");
  try {
    RoombaBt roomba(RoombaParams{}, 1, path);
    FAIL() << "the tree was accepted";
  } catch (const bt::TreeFileError& e) {
    EXPECT_EQ(e.what(), path + ":4: <Rotate>: a leaf cannot have children");
    EXPECT_EQ(e.line(), 4);
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace roomba_rrt::behavior
