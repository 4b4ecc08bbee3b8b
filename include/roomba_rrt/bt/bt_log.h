// Behavior-tree log files in BehaviorTree.CPP 4's FileLogger2 format (`.btlog`), which Groot2
// replays: the tree's XML with a `_uid` on every node, the start time, then one 9-byte record
// per status change.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

/// A node's status as the log stores it: BT.CPP's NodeStatus values (IDLE is a node that is
/// not running and was reset, e.g. by a halt or its parent finishing).
enum class LogStatus : std::uint8_t {
  kIdle = 0,
  kRunning = 1,
  kSuccess = 2,
  kFailure = 3,
  kSkipped = 4
};

/// "IDLE", "RUNNING", "SUCCESS", "FAILURE", "SKIPPED" ("?" for another byte).
const char* toString(LogStatus status);

/// One status change: microseconds since the log's start, the node's `_uid`, its new status.
struct LogTransition {
  std::uint64_t usec = 0;  ///< stored in 6 bytes: at most 2^48 - 1 (about 8.9 years)
  std::uint16_t uid = 0;
  LogStatus status = LogStatus::kIdle;
  bool operator==(const LogTransition& o) const {
    return usec == o.usec && uid == o.uid && status == o.status;
  }
};

/// A whole log, as read back.
struct BtLog {
  std::string tree_xml;         ///< the tree, `_uid` on every node
  std::int64_t start_usec = 0;  ///< microseconds since the Unix epoch
  std::vector<LogTransition> transitions;
};

/// Writes a FileLogger2 log to `out` (opened in binary mode): the header at construction, then
/// each transition as it comes, little-endian as BT.CPP writes it on x86:
///
///     "BTCPP4-FileLogger2"  1 byte protocol (1)  int32 XML size N  N bytes XML
///     int64 start (µs since the epoch)  { 6 bytes µs since start, uint16 uid, uint8 status }*
class BtLogWriter {
 public:
  BtLogWriter(std::ostream& out, const std::string& tree_xml, std::int64_t start_usec);
  /// Appends one record (a time beyond 6 bytes is clamped to 2^48 - 1).
  void write(const LogTransition& transition);

 private:
  std::ostream& out_;
};

/// Reads a FileLogger2 log (ours or BT.CPP's). util::InvalidInput naming what is wrong: not a
/// FileLogger2 file, another protocol, a size beyond the file, a record cut short.
BtLog readBtLog(std::istream& in, const std::string& source);
BtLog readBtLogFile(const std::string& path);

/// Prints `log` as text, one line per transition: seconds since the start, the node's path
/// (the names from the root down, from the XML), and the change, e.g.
/// "    1.250000  Roomba/root/clean/MoveForward  RUNNING -> FAILURE". A uid the XML does not
/// name is printed as "#uid".
void printBtLog(const BtLog& log, std::ostream& out);

}  // namespace roomba_rrt::bt
