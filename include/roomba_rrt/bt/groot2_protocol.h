// Groot2's monitoring protocol (BehaviorTree.CPP 4.x, protocol version 2), without sockets: the
// headers, the status snapshot and the reply to each request. groot2_server.h puts it on ZeroMQ.
//
// Every exchange is a multipart ZeroMQ request and reply. A request starts with a 6-byte header:
// protocol (uint8, 2), type (one character: 'T', 'S', ...), request id (uint32, little-endian);
// the reply starts with the same 6 bytes (protocol 2) followed by the tree's 16-byte UUID, 22
// bytes, then the payload. A bad request gets two frames, "error" and why, as BehaviorTree.CPP's
// Groot2Publisher answers.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/tree_monitor.h"

namespace roomba_rrt::bt::groot2 {

constexpr std::uint8_t kProtocolId = 2;
constexpr std::size_t kRequestHeaderSize = 6;
constexpr std::size_t kReplyHeaderSize = 22;

/// The request types of BehaviorTree.CPP's groot2_protocol.h.
enum RequestType : char {
  kFullTree = 'T',    ///< the tree's XML with a _uid on every node, and its model
  kStatus = 'S',      ///< uid (uint16) + status (uint8) of every node
  kBlackboard = 'B',  ///< blackboard dump (msgpack)
  kHookInsert = 'I',  ///< breakpoints and hooks (not supported here)
  kHookRemove = 'R',
  kBreakpointReached = 'N',  ///< sent by the executor on the PUB socket
  kBreakpointUnlock = 'U',
  kHooksDump = 'D',
  kRemoveAllHooks = 'A',
  kDisableAllHooks = 'X',
  kToggleRecording = 'r',
  kGetTransitions = 't',
};

using TreeUuid = std::array<char, 16>;

struct RequestHeader {
  std::uint8_t protocol = kProtocolId;
  char type = 0;
  std::uint32_t id = 0;
};

/// The 6 bytes of `header`.
std::string encodeRequestHeader(const RequestHeader& header);
/// The header in `bytes`, or nothing when they are not exactly 6 bytes.
std::optional<RequestHeader> decodeRequestHeader(const std::string& bytes);
/// The 22 bytes of a reply to `request`: its type and id, protocol 2, then `uuid`.
std::string encodeReplyHeader(const RequestHeader& request, const TreeUuid& uuid);
/// A random version-4 UUID (RFC 4122), drawn once per tree: Groot2 sees a new UUID when the
/// executor restarts and fetches the tree again.
TreeUuid randomUuid();

/// The payload of a 'S' reply: uid (uint16, little-endian) and status (MonitorStatus, uint8) of
/// every node, in the monitor's order. `out` is reused (no allocation once it has grown).
void statusSnapshot(const TreeMonitor& monitor, std::string& out);

/// One blackboard entry as JSON can hold it: bool, integer, number or string; a value of another
/// type (a pose, a path) as the string "<TypeName>".
struct BlackboardValue {
  enum class Kind { kBool, kInteger, kNumber, kString };
  std::string key;
  Kind kind = Kind::kString;
  bool boolean = false;
  std::int64_t integer = 0;
  double number = 0;
  std::string text;
};
using BlackboardSnapshot = std::vector<BlackboardValue>;

/// Every written entry of `blackboard`, by key (taken in the thread that ticks the tree).
BlackboardSnapshot snapshotBlackboard(const Blackboard& blackboard);

/// The payload of a 'B' reply, as BehaviorTree.CPP's: MessagePack of a JSON object whose keys are
/// the requested blackboard names (`names`, separated by ';') that exist, each an object of
/// key -> value. Our trees have one blackboard, named as the tree (`tree_id`, the 'T' reply's
/// <BehaviorTree ID>); other names are left out.
std::string blackboardDump(const std::string& names, const std::string& tree_id,
                           const BlackboardSnapshot& snapshot);

/// What the server knows when it answers.
struct ServerState {
  TreeUuid uuid{};
  std::string tree_xml;  ///< treeXmlWithUids()
  std::string status;    ///< the latest statusSnapshot()
  std::string tree_id;   ///< the name of the one blackboard
  /// The blackboard, when the tree's thread provided it for this request ('B').
  std::optional<BlackboardSnapshot> blackboard;
};

/// The reply frames to the request frames `request`:
/// - 'T': header, tree XML; 'S': header, status snapshot;
/// - 'D' (hooks dump): header, "[]"; 'A', 'X' (remove or disable every hook): header;
/// - 'B' with 2 frames (header, names): header, blackboardDump() of the state's blackboard;
/// - "error" and a reason for: a first frame that is not 6 bytes ("wrong request header", also
///   for no frame), 'B' without exactly 2 frames ("must be 2 parts message"), 'B' without a
///   blackboard in the state (the tree is not ticking), 'I', 'R', 'U', 'r', 't' (breakpoints and
///   recording are not supported by this server), and any other type ("Request not
///   recognized").
/// The protocol byte is not checked (BehaviorTree.CPP does not either): the reply carries 2, so a
/// client of another version can tell.
std::vector<std::string> reply(const std::vector<std::string>& request, const ServerState& state);

}  // namespace roomba_rrt::bt::groot2
