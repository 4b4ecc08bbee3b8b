#include "roomba_rrt/bt/groot2_protocol.h"

#include <algorithm>
#include <cstring>
#include <random>

namespace roomba_rrt::bt::groot2 {
namespace {

void putLittleEndian(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

std::vector<std::string> error(const std::string& why) { return {"error", why}; }

void putBigEndian(std::string& out, std::uint64_t value, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

// MessagePack (msgpack.org's spec), the few types a blackboard dump needs.
void packMap(std::string& out, std::size_t size) {
  if (size < 16) {
    out.push_back(static_cast<char>(0x80 | size));
  } else {
    out.push_back(static_cast<char>(0xdf));
    putBigEndian(out, size, 4);
  }
}
void packString(std::string& out, const std::string& s) {
  if (s.size() < 32) {
    out.push_back(static_cast<char>(0xa0 | s.size()));
  } else {
    out.push_back(static_cast<char>(0xdb));
    putBigEndian(out, s.size(), 4);
  }
  out += s;
}
void packValue(std::string& out, const BlackboardValue& v) {
  using Kind = BlackboardValue::Kind;
  switch (v.kind) {
    case Kind::kBool:
      out.push_back(static_cast<char>(v.boolean ? 0xc3 : 0xc2));
      return;
    case Kind::kInteger:
      out.push_back(static_cast<char>(0xd3));
      putBigEndian(out, static_cast<std::uint64_t>(v.integer), 8);
      return;
    case Kind::kNumber: {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &v.number, sizeof(bits));
      out.push_back(static_cast<char>(0xcb));
      putBigEndian(out, bits, 8);
      return;
    }
    case Kind::kString:
      packString(out, v.text);
      return;
  }
}

/// The value of `entry` if it holds T.
template <class T>
const T* valueOf(const Blackboard::EntryBase& entry) {
  const auto* typed = dynamic_cast<const Blackboard::Entry<T>*>(&entry);
  return typed ? typed->get() : nullptr;
}

}  // namespace

std::string encodeRequestHeader(const RequestHeader& header) {
  std::string out;
  out.push_back(static_cast<char>(header.protocol));
  out.push_back(header.type);
  putLittleEndian(out, header.id, 4);
  return out;
}

std::optional<RequestHeader> decodeRequestHeader(const std::string& bytes) {
  if (bytes.size() != kRequestHeaderSize) return std::nullopt;
  RequestHeader header;
  header.protocol = static_cast<std::uint8_t>(bytes[0]);
  header.type = bytes[1];
  header.id = 0;
  for (int i = 0; i < 4; ++i) {
    header.id |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[2 + i])) << (8 * i);
  }
  return header;
}

std::string encodeReplyHeader(const RequestHeader& request, const TreeUuid& uuid) {
  RequestHeader header = request;
  header.protocol = kProtocolId;
  std::string out = encodeRequestHeader(header);
  out.append(uuid.data(), uuid.size());
  return out;
}

TreeUuid randomUuid() {
  std::random_device device;
  TreeUuid uuid{};
  for (char& byte : uuid) byte = static_cast<char>(device() & 0xFF);
  uuid[6] = static_cast<char>((uuid[6] & 0x0F) | 0x40);  // version 4
  uuid[8] = static_cast<char>((uuid[8] & 0x3F) | 0x80);  // variant 10xxxxxx
  return uuid;
}

void statusSnapshot(const TreeMonitor& monitor, std::string& out) {
  out.clear();
  const auto& nodes = monitor.nodes();
  const auto& statuses = monitor.statuses();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    putLittleEndian(out, nodes[i].uid, 2);
    out.push_back(static_cast<char>(statuses[i]));
  }
}

BlackboardSnapshot snapshotBlackboard(const Blackboard& blackboard) {
  using Kind = BlackboardValue::Kind;
  BlackboardSnapshot snapshot;
  blackboard.forEach([&](const std::string& key, const Blackboard::EntryBase& entry) {
    if (entry.writes == 0) return;  // never written: nothing to show
    BlackboardValue v;
    v.key = key;
    if (const bool* b = valueOf<bool>(entry)) {
      v.kind = Kind::kBool;
      v.boolean = *b;
    } else if (const int* i = valueOf<int>(entry)) {
      v.kind = Kind::kInteger;
      v.integer = *i;
    } else if (const long* l = valueOf<long>(entry)) {
      v.kind = Kind::kInteger;
      v.integer = *l;
    } else if (const double* d = valueOf<double>(entry)) {
      v.kind = Kind::kNumber;
      v.number = *d;
    } else if (const std::string* s = valueOf<std::string>(entry)) {
      v.text = *s;
    } else {
      v.text = "<" + entry.type_name + ">";
    }
    snapshot.push_back(std::move(v));
  });
  return snapshot;
}

std::string blackboardDump(const std::string& names, const std::string& tree_id,
                           const BlackboardSnapshot& snapshot) {
  bool found = false;  // the one blackboard, however often it is named
  std::size_t start = 0;
  while (start <= names.size()) {
    const std::size_t end = std::min(names.find(';', start), names.size());
    found = found || names.compare(start, end - start, tree_id) == 0;
    start = end + 1;
  }
  std::string out;
  packMap(out, found ? 1 : 0);
  if (!found) return out;
  packString(out, tree_id);
  packMap(out, snapshot.size());
  for (const BlackboardValue& v : snapshot) {
    packString(out, v.key);
    packValue(out, v);
  }
  return out;
}

std::vector<std::string> reply(const std::vector<std::string>& request, const ServerState& state) {
  const std::optional<RequestHeader> header =
      request.empty() ? std::nullopt : decodeRequestHeader(request.front());
  if (!header) return error("wrong request header");
  std::vector<std::string> frames{encodeReplyHeader(*header, state.uuid)};
  switch (header->type) {
    case kFullTree:
      frames.push_back(state.tree_xml);
      return frames;
    case kStatus:
      frames.push_back(state.status);
      return frames;
    case kHooksDump:
      frames.emplace_back("[]");  // no hooks, ever
      return frames;
    case kRemoveAllHooks:
    case kDisableAllHooks:
      return frames;  // nothing to remove or disable (Groot2 sends these when it disconnects)
    case kBlackboard:
      if (request.size() != 2) return error("must be 2 parts message");
      if (!state.blackboard) return error("the tree is not ticking: no blackboard to dump");
      frames.push_back(blackboardDump(request[1], state.tree_id, *state.blackboard));
      return frames;
    case kHookInsert:
    case kHookRemove:
    case kBreakpointUnlock:
      return error("roomba_bt does not support breakpoints");
    case kToggleRecording:
    case kGetTransitions:
      return error("roomba_bt does not record transitions (use a log file)");
    default:
      return error("Request not recognized");
  }
}

}  // namespace roomba_rrt::bt::groot2
