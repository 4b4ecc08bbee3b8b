#include "roomba_rrt/bt/node_conditions.h"

namespace roomba_rrt::bt {
namespace {

/// Runs `script` if there is one; false when it cannot be evaluated.
bool run(const std::optional<Script>& script, Blackboard& board) {
  if (!script) return true;
  try {
    script->evaluate(board);
    return true;
  } catch (const ScriptError&) {
    return false;
  }
}

/// What a pre-condition decides: nothing (tick the node), or its status.
enum class Verdict { kTick, kSuccess, kFailure, kSkip };

/// `script` (if any) true gives `verdict`; one that cannot be evaluated fails the node.
Verdict check(const std::optional<Script>& script, Blackboard& board, Verdict verdict) {
  if (!script) return Verdict::kTick;
  try {
    return script->isTrue(board) ? verdict : Verdict::kTick;
  } catch (const ScriptError&) {
    return Verdict::kFailure;
  }
}

}  // namespace

bool NodeConditions::isConditionAttribute(const std::string& attribute) {
  return attribute == "_failureIf" || attribute == "_successIf" || attribute == "_skipIf" ||
         attribute == "_while" || attribute == "_onSuccess" || attribute == "_onFailure" ||
         attribute == "_post" || attribute == "_onHalted";
}

void NodeConditions::set(const std::string& attribute, Script script) {
  std::optional<Script>& slot = attribute == "_failureIf"   ? failure_if
                                : attribute == "_successIf" ? success_if
                                : attribute == "_skipIf"    ? skip_if
                                : attribute == "_while"     ? while_true
                                : attribute == "_onSuccess" ? on_success
                                : attribute == "_onFailure" ? on_failure
                                : attribute == "_post"      ? post
                                                            : on_halted;
  slot = std::move(script);
}

std::optional<Status> NodeConditions::before(bool running) const {
  Verdict verdict = Verdict::kTick;
  if (!running) {
    verdict = check(failure_if, *board, Verdict::kFailure);
    if (verdict == Verdict::kTick) verdict = check(success_if, *board, Verdict::kSuccess);
    if (verdict == Verdict::kTick) verdict = check(skip_if, *board, Verdict::kSkip);
  }
  if (verdict == Verdict::kTick && while_true) {
    try {
      if (!while_true->isTrue(*board)) verdict = Verdict::kSkip;
    } catch (const ScriptError&) {
      verdict = Verdict::kFailure;
    }
  }
  switch (verdict) {
    case Verdict::kSuccess:
      return Status::kSuccess;
    case Verdict::kFailure:
      return Status::kFailure;
    case Verdict::kSkip:
      return Status::kSkipped;
    case Verdict::kTick:
      break;
  }
  return std::nullopt;
}

Status NodeConditions::after(Status status) const {
  const bool ran =
      run(status == Status::kSuccess ? on_success : on_failure, *board) && run(post, *board);
  return ran ? status : Status::kFailure;
}

void NodeConditions::halted() const { run(on_halted, *board); }

}  // namespace roomba_rrt::bt
