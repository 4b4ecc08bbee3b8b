#include "roomba_rrt/bt/groot2_protocol.h"

#include <random>

namespace roomba_rrt::bt::groot2 {
namespace {

void putLittleEndian(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

std::vector<std::string> error(const std::string& why) { return {"error", why}; }

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
      return error("roomba_bt does not dump its blackboard");
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
