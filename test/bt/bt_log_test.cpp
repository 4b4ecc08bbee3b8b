// .btlog files (BehaviorTree.CPP's FileLogger2 format): written and read back the same, the bytes
// where BT.CPP puts them, damaged files refused, and the text roomba_bt --print-log prints.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "roomba_rrt/bt/bt_file_logger.h"
#include "roomba_rrt/bt/bt_log.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "scripted_leaf.h"

namespace roomba_rrt::bt {
namespace {

const std::string kXml = R"(<root BTCPP_format="4"><BehaviorTree ID="Roomba">
<Fallback name="root" _uid="1"><Sequence name="clean" _uid="2"><MoveForward _uid="3"/>
<MoveInSpiral _uid="4"/></Sequence><Action ID="GoBack" _uid="5"/></Fallback>
</BehaviorTree></root>)";

std::vector<LogTransition> someTransitions() {
  return {
      {0, 1, LogStatus::kRunning},       {0, 2, LogStatus::kRunning},
      {16667, 3, LogStatus::kRunning},   {1250000, 3, LogStatus::kFailure},
      {1250000, 5, LogStatus::kRunning}, {(std::uint64_t{1} << 48) - 1, 65535, LogStatus::kIdle}};
}

std::string written(const std::vector<LogTransition>& transitions) {
  std::ostringstream out(std::ios::binary);
  BtLogWriter writer(out, kXml, 1764300000123456);
  for (const auto& t : transitions) writer.write(t);
  return out.str();
}

std::string readError(const std::string& bytes) {
  std::istringstream in(bytes, std::ios::binary);
  try {
    readBtLog(in, "run.btlog");
  } catch (const util::InvalidInput& e) {
    return e.what();
  }
  return "no error";
}

TEST(BtLog, what_is_written_is_read_back) {
  const std::string bytes = written(someTransitions());
  std::istringstream in(bytes, std::ios::binary);
  const BtLog log = readBtLog(in, "run.btlog");
  EXPECT_EQ(log.tree_xml, kXml);
  EXPECT_EQ(log.start_usec, 1764300000123456);
  EXPECT_EQ(log.transitions, someTransitions());
}

TEST(BtLog, the_bytes_are_where_bt_cpp_s_file_logger_2_puts_them) {
  const std::string bytes = written({{0x010203040506, 0x0708, LogStatus::kFailure}});
  ASSERT_EQ(bytes.size(), 18 + 1 + 4 + kXml.size() + 8 + 9);
  EXPECT_EQ(bytes.substr(0, 18), "BTCPP4-FileLogger2");
  EXPECT_EQ(bytes[18], 1);                                               // protocol
  EXPECT_EQ(static_cast<unsigned char>(bytes[19]), kXml.size() & 0xff);  // little-endian size
  EXPECT_EQ(bytes.substr(23, kXml.size()), kXml);
  const std::string record = bytes.substr(bytes.size() - 9);
  EXPECT_EQ(record, std::string("\x06\x05\x04\x03\x02\x01\x08\x07\x03", 9));
}

TEST(BtLog, damaged_files_are_refused_saying_what_is_wrong) {
  const std::string bytes = written(someTransitions());
  EXPECT_EQ(readError("BTCPP4-FileLogger1\x01"),
            "run.btlog: not a BehaviorTree.CPP FileLogger2 log (no \"BTCPP4-FileLogger2\" header)");
  EXPECT_EQ(readError("BTCP"), "run.btlog: the header is cut short");
  std::string protocol = bytes;
  protocol[18] = 2;
  EXPECT_EQ(readError(protocol), "run.btlog: protocol 2 is not supported (1)");
  EXPECT_EQ(readError(bytes.substr(0, 40)), "run.btlog: the tree's XML is cut short");
  EXPECT_EQ(readError(bytes.substr(0, bytes.size() - 4)),
            "run.btlog: transition 6 is cut short (5 of 9 bytes)");
  std::string huge = bytes.substr(0, 23);
  huge[22] = '\x7f';
  EXPECT_NE(readError(huge).find("is beyond the limit"), std::string::npos);
}

TEST(BtLog, prints_time_path_and_change_per_transition) {
  BtLog log;
  log.tree_xml = kXml;
  log.transitions = {{16667, 3, LogStatus::kRunning},
                     {1250000, 3, LogStatus::kFailure},
                     {1250000, 5, LogStatus::kRunning},
                     {1266667, 9, LogStatus::kSuccess}};
  std::ostringstream out;
  printBtLog(log, out);
  EXPECT_EQ(out.str(),
            "    0.016667  Roomba/root/clean/MoveForward  IDLE -> RUNNING\n"
            "    1.250000  Roomba/root/clean/MoveForward  RUNNING -> FAILURE\n"
            "    1.250000  Roomba/root/GoBack  IDLE -> RUNNING\n"
            "    1.266667  #9  IDLE -> SUCCESS\n");
}

/// A tree from a file, recorded: Fallback(Sequence(MoveForward, Spiral), GoBack).
struct Recorded {
  static constexpr Status S = Status::kSuccess, F = Status::kFailure, R = Status::kRunning;
  TreeFactory leaves() {
    TreeFactory f;
    f.registerLeaf("MoveForward", [this](const NodeSpec& s) {
      return testing::scripted(&forward, {R, F, R}, s.name);
    });
    f.registerLeaf("Spiral", [](const NodeSpec& s) {
      return std::make_unique<testing::ScriptedLeaf>(s.name, std::vector<Status>{R});
    });
    f.registerLeaf("GoBack",
                   [this](const NodeSpec& s) { return testing::scripted(&back, {S}, s.name); });
    return f;
  }
  testing::ScriptedLeaf* forward = nullptr;
  testing::ScriptedLeaf* back = nullptr;
  TreeFactory factory = leaves();
  Tree tree = factory.buildFromText(R"(<root BTCPP_format="4"><BehaviorTree>
    <Fallback name="root"><Sequence name="clean"><MoveForward/><Spiral/></Sequence><GoBack/>
    </Fallback></BehaviorTree></root>)");
  std::int64_t now = 1000000;
};

TEST(BtFileLogger, writes_the_tree_with_uids_in_depth_first_order) {
  Recorded r;
  EXPECT_EQ(treeXmlWithUids(r.tree.root(), "Roomba"),
            "<root BTCPP_format=\"4\" main_tree_to_execute=\"Roomba\">\n"
            "    <BehaviorTree ID=\"Roomba\">\n"
            "        <Fallback name=\"root\" _uid=\"1\">\n"
            "            <Sequence name=\"clean\" _uid=\"2\">\n"
            "                <MoveForward _uid=\"3\"/>\n"
            "                <Spiral _uid=\"4\"/>\n"
            "            </Sequence>\n"
            "            <GoBack _uid=\"5\"/>\n"
            "        </Fallback>\n"
            "    </BehaviorTree>\n"
            "</root>\n");
  const std::string with_model =
      treeXmlWithUids(r.tree.root(), "Roomba", r.factory.treeNodesModel());
  EXPECT_NE(with_model.find("<Action ID=\"GoBack\"/>"), std::string::npos) << with_model;
}

TEST(BtFileLogger, records_each_change_with_resets_to_idle_as_bt_cpp_does) {
  Recorded r;
  std::ostringstream out(std::ios::binary);
  {
    BtFileLogger logger(r.tree, out, "Roomba", "", [&r] { return r.now; });
    r.tree.tick();  // MoveForward RUNNING
    r.now += 16667;
    r.tree.tick();  // MoveForward FAILURE: GoBack SUCCESS, root SUCCESS
    r.now += 16667;
    r.tree.tick();  // the root again: MoveForward RUNNING
    r.tree.halt();
    EXPECT_EQ(logger.transitions(), 16u);
  }
  std::istringstream in(out.str(), std::ios::binary);
  const BtLog log = readBtLog(in, "run.btlog");
  EXPECT_EQ(log.start_usec, 1000000);
  std::ostringstream text;
  printBtLog(log, text);
  EXPECT_EQ(text.str(),
            "    0.000000  Roomba/root/clean/MoveForward  IDLE -> RUNNING\n"
            "    0.000000  Roomba/root/clean  IDLE -> RUNNING\n"
            "    0.000000  Roomba/root  IDLE -> RUNNING\n"
            "    0.016667  Roomba/root/clean/MoveForward  RUNNING -> FAILURE\n"
            "    0.016667  Roomba/root/clean/MoveForward  FAILURE -> IDLE\n"
            "    0.016667  Roomba/root/clean  RUNNING -> FAILURE\n"
            "    0.016667  Roomba/root/GoBack  IDLE -> SUCCESS\n"
            "    0.016667  Roomba/root/clean  FAILURE -> IDLE\n"
            "    0.016667  Roomba/root/GoBack  SUCCESS -> IDLE\n"
            "    0.016667  Roomba/root  RUNNING -> SUCCESS\n"
            "    0.033334  Roomba/root/clean/MoveForward  IDLE -> RUNNING\n"
            "    0.033334  Roomba/root/clean  IDLE -> RUNNING\n"
            "    0.033334  Roomba/root  SUCCESS -> RUNNING\n"
            "    0.033334  Roomba/root/clean/MoveForward  RUNNING -> IDLE\n"
            "    0.033334  Roomba/root/clean  RUNNING -> IDLE\n"
            "    0.033334  Roomba/root  RUNNING -> IDLE\n");
  // Detached: the tree ticks without it.
  EXPECT_EQ(r.tree.tick(), Status::kRunning);
}

TEST(BtFileLogger, a_tree_records_into_a_file_it_owns_until_the_log_stops) {
  Recorded r;
  const std::string path = ::testing::TempDir() + "bt_log_test.btlog";
  r.tree.startLog(std::make_unique<std::ofstream>(path, std::ios::binary), "Roomba", "",
                  [&r] { return r.now; });
  r.tree.tick();
  r.now += 16667;
  r.tree.tick();
  ASSERT_NE(r.tree.logger(), nullptr);
  const std::size_t written = r.tree.logger()->transitions();
  r.tree.stopLog();
  EXPECT_EQ(r.tree.logger(), nullptr);
  r.tree.tick();  // not recorded
  const BtLog log = readBtLogFile(path);
  EXPECT_EQ(log.transitions.size(), written);
  EXPECT_EQ(log.transitions.size(), 10u);
  EXPECT_EQ(log.transitions.back(), (LogTransition{16667, 1, LogStatus::kSuccess}));
  std::remove(path.c_str());
}

}  // namespace
}  // namespace roomba_rrt::bt
