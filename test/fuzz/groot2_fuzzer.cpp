// libFuzzer harness: a Groot2 request (its frames drawn from the input) → groot2::reply() on a
// tree's state, as roomba_bt's server answers it. Every request gets an answer Groot2 can read:
// BehaviorTree.CPP's error reply ("error" and a reason), or the 22-byte reply header echoing the
// request's type and id with protocol 2 and the tree's UUID.
#include <fuzzer/FuzzedDataProvider.h>

#include <string>
#include <vector>

#include "request_fuzzing.h"
#include "roomba_rrt/bt/groot2_protocol.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace groot2 = roomba_rrt::bt::groot2;
  using roomba_rrt::fuzz::require;
  constexpr const char* kHarness = "groot2_fuzzer";
  FuzzedDataProvider in(data, size);

  groot2::ServerState state;
  state.uuid = groot2::TreeUuid{'u', 'u', 'i', 'd'};
  state.tree_xml = "<root BTCPP_format=\"4\"/>";
  state.status = std::string("\x01\x00\x01", 3);
  state.tree_id = "Roomba";
  if (in.ConsumeBool()) {
    groot2::BlackboardValue value;
    value.key = in.ConsumeRandomLengthString(16);
    value.text = in.ConsumeRandomLengthString(64);
    state.blackboard = groot2::BlackboardSnapshot{value};
  }
  std::vector<std::string> request;
  const int frames = in.ConsumeIntegralInRange(0, 4);
  for (int i = 0; i < frames; ++i) {
    // Often a well-formed header, so that every request type is reached.
    if (i == 0 && in.ConsumeBool()) {
      request.push_back(groot2::encodeRequestHeader({in.ConsumeIntegral<std::uint8_t>(),
                                                     in.ConsumeIntegral<char>(),
                                                     in.ConsumeIntegral<std::uint32_t>()}));
    } else {
      request.push_back(in.ConsumeRandomLengthString(4096));
    }
  }

  const std::vector<std::string> reply = groot2::reply(request, state);
  require(!reply.empty(), kHarness, "an empty reply");
  if (reply[0] == "error") {
    require(reply.size() == 2 && !reply[1].empty(), kHarness, "an error reply without a reason");
    return 0;
  }
  const auto header = groot2::decodeRequestHeader(request.empty() ? "" : request[0]);
  require(header.has_value(), kHarness, "a reply to a request without a header");
  require(reply[0].size() == groot2::kReplyHeaderSize, kHarness, "a reply header not 22 bytes");
  require(reply[0][0] == groot2::kProtocolId, kHarness, "a reply not of protocol 2");
  require(reply[0][1] == header->type, kHarness, "a reply of another type");
  require(reply[0].substr(2, 4) == request[0].substr(2, 4), kHarness, "a reply with another id");
  require(reply[0].substr(6) == std::string(state.uuid.data(), 16), kHarness, "another UUID");
  return 0;
}
