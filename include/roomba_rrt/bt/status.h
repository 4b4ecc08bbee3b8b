// The result of ticking a behavior-tree node.
#pragma once

#include <cstdint>

namespace roomba_rrt::bt {

/// What a node reports after one tick.
///
/// - kSuccess: the node finished and achieved its goal; it is no longer running.
/// - kFailure: the node finished without achieving its goal; it is no longer running.
/// - kRunning: the node needs more ticks; its parent ticks it again (without entering it anew).
/// - kSkipped: the node was not executed (BehaviorTree.CPP 4's SKIPPED: a `_skipIf` held, a
///   `_while` did not, RunOnce ran before); it is not running, and a composite goes on as if the
///   child were not there (one whose children were all skipped is skipped itself).
enum class Status : std::uint8_t { kSuccess, kFailure, kRunning, kSkipped };

/// "SUCCESS", "FAILURE" or "RUNNING" (for logs and test messages).
const char* toString(Status status);

/// Throws std::logic_error: `node` received a status outside the enum from a child. Composites
/// call it from the `default:` of their status switch, so an impossible status is never ignored.
[[noreturn]] void throwImpossibleStatus(const char* node, Status status);

}  // namespace roomba_rrt::bt
