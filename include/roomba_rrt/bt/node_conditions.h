// BehaviorTree.CPP's pre- and post-conditions: scripts in a node's attributes that decide
// whether it is ticked (`_failureIf`, `_successIf`, `_skipIf`, `_while`) and run when it finishes
// (`_onSuccess`,
// `_onFailure`, `_post`) or is halted (`_onHalted`).
#pragma once

#include <optional>
#include <string>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/script.h"
#include "roomba_rrt/bt/status.h"

namespace roomba_rrt::bt {

/// The condition scripts of one node, and the blackboard they run on.
///
/// When the node is ticked and is not running:
/// - `_failureIf` true: it returns FAILURE without being entered or ticked;
/// - else `_successIf` true: it returns SUCCESS likewise;
/// - else `_skipIf` true, or `_while` false: it returns SKIPPED likewise;
/// - else it is entered and ticked as usual.
/// While it is running only `_while` is checked: false halts the node, which returns SKIPPED.
/// When it returns SUCCESS (ticked, or by `_successIf`), `_onSuccess` runs; on FAILURE,
/// `_onFailure`; on either, `_post` after that. When it is halted, `_onHalted` runs.
///
/// A script that cannot be evaluated (ScriptError: a key never written, a type mismatch) fails
/// the node: the pre-condition returns FAILURE without ticking it, a post-condition turns the
/// result into FAILURE (BT.CPP throws an exception from the tick instead).
struct NodeConditions {
  Blackboard* board = nullptr;
  std::optional<Script> failure_if, success_if, skip_if, while_true;
  std::optional<Script> on_success, on_failure, post, on_halted;

  /// What the pre-conditions decide: nullopt (tick it), or the status the node returns without
  /// being ticked (SKIPPED for a `running` node means: halt it first).
  std::optional<Status> before(bool running) const;
  /// Runs the post-conditions for a node that finished with `status`: `status`, or FAILURE when
  /// one of them cannot be evaluated.
  Status after(Status status) const;
  /// Runs `_onHalted`.
  void halted() const;

  /// The attributes the factory reads into a NodeConditions.
  static bool isConditionAttribute(const std::string& attribute);
  /// Sets the script of `attribute` (one isConditionAttribute() accepts).
  void set(const std::string& attribute, Script script);
};

}  // namespace roomba_rrt::bt
