#include "roomba_rrt/bt/entry_updated.h"

namespace roomba_rrt::bt {

std::uint64_t writesOf(const Blackboard& board, const std::string& key) {
  const Blackboard::EntryBase* entry = board.find(key);
  return entry ? entry->writes : 0;
}

Status WasEntryUpdated::onTick() {
  const std::uint64_t writes = writesOf(board_, key_);
  const bool updated = writes != seen_;
  seen_ = writes;
  return updated ? Status::kSuccess : Status::kFailure;
}

Status EntryUpdatedDecorator::onTick() {
  if (!child_->isRunning()) {
    const std::uint64_t writes = writesOf(board_, key_);
    if (writes == seen_) return if_not_updated_;
    seen_ = writes;
  }
  return child_->tick();
}

}  // namespace roomba_rrt::bt
