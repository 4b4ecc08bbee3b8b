// Groot2's protocol as BehaviorTree.CPP 4.x speaks it (groot2_protocol.h): headers, snapshots and
// the reply to every kind of request, good or bad.
#include <gtest/gtest.h>

#include <set>

#include "roomba_rrt/bt/groot2_protocol.h"
#include "roomba_rrt/bt/sequence_node.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt::groot2 {
namespace {

using bt::testing::R;
using bt::testing::ScriptedLeaf;

std::string header(char type, std::uint32_t id = 0x04030201, std::uint8_t protocol = 2) {
  return encodeRequestHeader({protocol, type, id});
}

ServerState someState() {
  ServerState state;
  state.uuid = randomUuid();
  state.tree_xml = "<root/>";
  state.status = std::string("\x01\x00\x01", 3);
  return state;
}

TEST(Groot2Header, a_request_header_is_protocol_type_and_little_endian_id_in_6_bytes) {
  EXPECT_EQ(header('S'), std::string("\x02S\x01\x02\x03\x04", 6));
  const auto decoded = decodeRequestHeader(header('T', 0xDEADBEEF, 7));
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->protocol, 7);
  EXPECT_EQ(decoded->type, 'T');
  EXPECT_EQ(decoded->id, 0xDEADBEEFu);
}

TEST(Groot2Header, anything_but_6_bytes_is_no_request_header) {
  EXPECT_FALSE(decodeRequestHeader(""));
  EXPECT_FALSE(decodeRequestHeader(std::string("\x02S\x01\x02\x03", 5)));
  EXPECT_FALSE(decodeRequestHeader(header('S') + "x"));
}

TEST(Groot2Header, a_reply_header_echoes_type_and_id_with_protocol_2_and_the_tree_uuid) {
  const TreeUuid uuid = randomUuid();
  const std::string reply = encodeReplyHeader({1, 'S', 0x04030201}, uuid);
  ASSERT_EQ(reply.size(), kReplyHeaderSize);
  EXPECT_EQ(reply.substr(0, 6), header('S'));
  EXPECT_EQ(reply.substr(6), std::string(uuid.data(), 16));
}

TEST(Groot2Header, uuids_are_random_version_4) {
  std::set<std::string> seen;
  for (int i = 0; i < 20; ++i) {
    const TreeUuid uuid = randomUuid();
    EXPECT_EQ(uuid[6] & 0xF0, 0x40);
    EXPECT_EQ(uuid[8] & 0xC0, 0x80);
    seen.insert(std::string(uuid.data(), 16));
  }
  EXPECT_EQ(seen.size(), 20u);
}

TEST(Groot2Status, the_snapshot_is_uid_and_status_of_every_node_3_bytes_each) {
  SequenceNode root("root");
  ScriptedLeaf* leaf = nullptr;
  root.addChild(bt::testing::scripted(&leaf, {R}));
  TreeMonitor monitor(root);
  std::string out;
  statusSnapshot(monitor, out);
  EXPECT_EQ(out, std::string("\x01\x00\x00\x02\x00\x00", 6));
  root.tick();
  monitor.update();
  statusSnapshot(monitor, out);
  EXPECT_EQ(out, std::string("\x01\x00\x01\x02\x00\x01", 6));
}

TEST(Groot2Reply, full_tree_and_status_carry_the_header_and_the_payload) {
  const ServerState state = someState();
  auto frames = reply({header('T')}, state);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0], encodeReplyHeader({2, 'T', 0x04030201}, state.uuid));
  EXPECT_EQ(frames[1], "<root/>");
  frames = reply({header('S'), "ignored"}, state);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1], state.status);
}

TEST(Groot2Reply, another_protocol_is_answered_as_version_2) {
  const auto frames = reply({header('S', 5, 1)}, someState());
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0][0], 2);
}

TEST(Groot2Reply, hooks_that_groot2_sends_on_connect_and_disconnect_are_answered) {
  const ServerState state = someState();
  EXPECT_EQ(reply({header('D')}, state),
            (std::vector<std::string>{encodeReplyHeader({2, 'D', 0x04030201}, state.uuid), "[]"}));
  EXPECT_EQ(reply({header('A')}, state).size(), 1u);
  EXPECT_EQ(reply({header('X')}, state).size(), 1u);
}

struct Pose {};  // a type JSON cannot hold

TEST(Groot2Blackboard, written_entries_by_key_as_json_values_others_by_type_name) {
  Blackboard board;
  board.set<bool>("bumped", true);
  board.set<int>("count", -3);
  board.set<double>("speed", 0.5);
  board.set<std::string>("error", "blocked");
  board.set<Pose>("pose", Pose{});
  board.declare<int>("never_written");
  const BlackboardSnapshot snapshot = snapshotBlackboard(board);
  ASSERT_EQ(snapshot.size(), 5u);
  EXPECT_EQ(snapshot[0].key, "bumped");
  EXPECT_TRUE(snapshot[0].boolean);
  EXPECT_EQ(snapshot[1].key, "count");
  EXPECT_EQ(snapshot[1].integer, -3);
  EXPECT_EQ(snapshot[2].text, "blocked");
  EXPECT_EQ(snapshot[3].text, "<" + TypeName<Pose>::get() + ">");
  EXPECT_EQ(snapshot[4].number, 0.5);
}

TEST(Groot2Blackboard, the_dump_is_messagepack_of_the_tree_blackboard_by_its_name) {
  Blackboard board;
  board.set<bool>("b", false);
  board.set<int>("i", 1);
  board.set<double>("d", 1.0);
  board.set<std::string>("s", "x");
  const BlackboardSnapshot snapshot = snapshotBlackboard(board);
  // {"Main": {"b": false, "d": 1.0, "i": 1, "s": "x"}}
  const std::string expected = std::string("\x81\xa4Main\x84", 7) +
                               "\xa1"
                               "b\xc2" +
                               std::string(
                                   "\xa1"
                                   "d\xcb\x3f\xf0\0\0\0\0\0\0",
                                   11) +
                               std::string(
                                   "\xa1"
                                   "i\xd3\0\0\0\0\0\0\0\x01",
                                   11) +
                               "\xa1"
                               "s\xa1"
                               "x";
  EXPECT_EQ(blackboardDump("Other;Main", "Main", snapshot), expected);
  EXPECT_EQ(blackboardDump("Other", "Main", snapshot), "\x80");  // an empty map
  ServerState state = someState();
  state.tree_id = "Main";
  state.blackboard = snapshot;
  const auto frames = reply({header('B'), "Main"}, state);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1], expected);
}

TEST(Groot2Reply, bad_requests_get_bt_cpp_error_replies) {
  const ServerState state = someState();
  const auto error = [](const std::string& why) { return std::vector<std::string>{"error", why}; };
  EXPECT_EQ(reply({}, state), error("wrong request header"));
  EXPECT_EQ(reply({"\x02S"}, state), error("wrong request header"));
  EXPECT_EQ(reply({std::string(1 << 20, 'x')}, state), error("wrong request header"));
  EXPECT_EQ(reply({header('?')}, state), error("Request not recognized"));
  EXPECT_EQ(reply({header('N')}, state), error("Request not recognized"));
  EXPECT_EQ(reply({header('B')}, state), error("must be 2 parts message"));
  for (char type : {'B', 'I', 'R', 'U', 'r', 't'}) {
    const auto frames = reply({header(type), "{}"}, state);
    ASSERT_EQ(frames.size(), 2u) << type;
    EXPECT_EQ(frames[0], "error") << type;
  }
}

}  // namespace
}  // namespace roomba_rrt::bt::groot2
