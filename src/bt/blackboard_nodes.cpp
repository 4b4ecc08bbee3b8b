#include "roomba_rrt/bt/blackboard_nodes.h"

#include "roomba_rrt/bt/ports.h"
#include "roomba_rrt/bt/script.h"

namespace roomba_rrt::bt {

Status SetBlackboard::onTick() {
  try {
    if (source_) {
      writeEntry(board_, output_key_, output_key_, readEntry(board_, *source_, *source_), true);
      return Status::kSuccess;
    }
    ScriptValue value = text_;  // a new key, or a string one, takes the text as it is
    const Blackboard::EntryBase* entry = board_.find(output_key_);
    if (entry && entry->type == typeid(bool)) {
      bool b = false;
      if (!LiteralParser<bool>::parse(text_, b).empty()) return Status::kFailure;
      value = b;
    } else if (entry && entry->type != typeid(std::string)) {
      double d = 0;
      if (!LiteralParser<double>::parse(text_, d).empty()) return Status::kFailure;
      value = d;
    }
    writeEntry(board_, output_key_, output_key_, value, true);
    return Status::kSuccess;
  } catch (const ScriptError&) {
    return Status::kFailure;
  }
}

}  // namespace roomba_rrt::bt
