#include "roomba_rrt/bt/bt_log.h"

#include <tinyxml2.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>

namespace roomba_rrt::bt {
namespace {

constexpr char kMagic[] = "BTCPP4-FileLogger2";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
constexpr std::uint8_t kProtocol = 1;
constexpr std::uint64_t kMaxUsec = (std::uint64_t{1} << 48) - 1;
/// A tree's XML larger than this is not a tree we wrote (and would exhaust memory to read).
constexpr std::uint32_t kMaxXmlBytes = 64u << 20;

/// `value`'s low `bytes` bytes, little-endian.
void putLittleEndian(std::ostream& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.put(static_cast<char>((value >> (8 * i)) & 0xff));
}

std::uint64_t getLittleEndian(const unsigned char* bytes, int count) {
  std::uint64_t value = 0;
  for (int i = count - 1; i >= 0; --i) value = (value << 8) | bytes[i];
  return value;
}

[[noreturn]] void refuse(const std::string& source, const std::string& problem) {
  throw util::InvalidInput("", problem, source);
}

/// Reads exactly `count` bytes or refuses, naming `what` was cut short.
void readExactly(std::istream& in, char* into, std::size_t count, const std::string& source,
                 const std::string& what) {
  in.read(into, static_cast<std::streamsize>(count));
  if (static_cast<std::size_t>(in.gcount()) != count) refuse(source, what + " is cut short");
}

/// Every node element with a `_uid`, by uid: its path of names from the root.
void collectPaths(const tinyxml2::XMLElement& element, const std::string& prefix,
                  std::map<unsigned, std::string>& paths) {
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    const char* name = child->Attribute("name");
    const char* id = child->Attribute("ID");
    const std::string path = prefix + "/" + (name ? name : id ? id : child->Name());
    const unsigned uid = child->UnsignedAttribute("_uid", 0);
    if (uid != 0) paths.emplace(uid, path);
    collectPaths(*child, path, paths);
  }
}

}  // namespace

const char* toString(LogStatus status) {
  switch (status) {
    case LogStatus::kIdle:
      return "IDLE";
    case LogStatus::kRunning:
      return "RUNNING";
    case LogStatus::kSuccess:
      return "SUCCESS";
    case LogStatus::kFailure:
      return "FAILURE";
    case LogStatus::kSkipped:
      return "SKIPPED";
  }
  return "?";
}

BtLogWriter::BtLogWriter(std::ostream& out, const std::string& tree_xml, std::int64_t start_usec)
    : out_(out) {
  out_.write(kMagic, kMagicSize);
  out_.put(static_cast<char>(kProtocol));
  putLittleEndian(out_, tree_xml.size(), 4);
  out_.write(tree_xml.data(), static_cast<std::streamsize>(tree_xml.size()));
  putLittleEndian(out_, static_cast<std::uint64_t>(start_usec), 8);
}

void BtLogWriter::write(const LogTransition& t) {
  putLittleEndian(out_, t.usec > kMaxUsec ? kMaxUsec : t.usec, 6);
  putLittleEndian(out_, t.uid, 2);
  out_.put(static_cast<char>(t.status));
}

BtLog readBtLog(std::istream& in, const std::string& source) {
  std::array<char, kMagicSize + 1> header{};
  readExactly(in, header.data(), header.size(), source, "the header");
  if (std::string(header.data(), kMagicSize) != kMagic) {
    refuse(source, "not a BehaviorTree.CPP FileLogger2 log (no \"BTCPP4-FileLogger2\" header)");
  }
  if (static_cast<std::uint8_t>(header[kMagicSize]) != kProtocol) {
    refuse(source, "protocol " + std::to_string(static_cast<unsigned char>(header[kMagicSize])) +
                       " is not supported (1)");
  }
  std::array<unsigned char, 8> bytes{};
  readExactly(in, reinterpret_cast<char*>(bytes.data()), 4, source, "the XML size");
  const auto xml_size = static_cast<std::uint32_t>(getLittleEndian(bytes.data(), 4));
  if (xml_size > kMaxXmlBytes) {
    refuse(source, "an XML size of " + std::to_string(xml_size) + " bytes is beyond the limit (" +
                       std::to_string(kMaxXmlBytes) + ")");
  }
  BtLog log;
  log.tree_xml.resize(xml_size);
  readExactly(in, log.tree_xml.data(), xml_size, source, "the tree's XML");
  readExactly(in, reinterpret_cast<char*>(bytes.data()), 8, source, "the start time");
  log.start_usec = static_cast<std::int64_t>(getLittleEndian(bytes.data(), 8));
  std::array<unsigned char, 9> record{};
  while (true) {
    in.read(reinterpret_cast<char*>(record.data()), record.size());
    const std::streamsize got = in.gcount();
    if (got == 0) break;
    if (got != static_cast<std::streamsize>(record.size())) {
      refuse(source, "transition " + std::to_string(log.transitions.size() + 1) +
                         " is cut short (" + std::to_string(got) + " of 9 bytes)");
    }
    LogTransition t;
    t.usec = getLittleEndian(record.data(), 6);
    t.uid = static_cast<std::uint16_t>(getLittleEndian(record.data() + 6, 2));
    t.status = static_cast<LogStatus>(record[8]);
    log.transitions.push_back(t);
  }
  return log;
}

BtLog readBtLogFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, "cannot open the file");
  return readBtLog(in, path);
}

void printBtLog(const BtLog& log, std::ostream& out) {
  std::map<unsigned, std::string> paths;
  tinyxml2::XMLDocument document;
  if (document.Parse(log.tree_xml.c_str(), log.tree_xml.size()) == tinyxml2::XML_SUCCESS &&
      document.RootElement()) {
    for (const auto* tree = document.RootElement()->FirstChildElement("BehaviorTree"); tree;
         tree = tree->NextSiblingElement("BehaviorTree")) {
      const char* id = tree->Attribute("ID");
      collectPaths(*tree, id ? id : "", paths);
    }
  }
  std::map<unsigned, LogStatus> current;  // every node starts IDLE
  for (const LogTransition& t : log.transitions) {
    const auto path = paths.find(t.uid);
    const LogStatus from = current.count(t.uid) ? current[t.uid] : LogStatus::kIdle;
    current[t.uid] = t.status;
    char time[32];
    std::snprintf(time, sizeof(time), "%12.6f", static_cast<double>(t.usec) / 1e6);
    out << time << "  " << (path != paths.end() ? path->second : "#" + std::to_string(t.uid))
        << "  " << toString(from) << " -> " << toString(t.status) << '\n';
  }
}

}  // namespace roomba_rrt::bt
