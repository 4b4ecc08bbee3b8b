#include "roomba_rrt/planning/stop_condition.h"

#include <algorithm>
#include <utility>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::planning {
namespace {

constexpr std::int64_t kMaxStride = 1024;
constexpr auto kShortInterval = std::chrono::milliseconds(1);  // below: read the clock less often
constexpr auto kLongInterval = std::chrono::milliseconds(2);   // above: read it more often

}  // namespace

StopCondition::StopCondition(double max_seconds, std::function<bool()> requested)
    : max_seconds_(max_seconds > 0 ? max_seconds : 0), requested_(std::move(requested)) {
  if (max_seconds_ == 0 && !requested_) return;  // countdown_ stays at INT64_MAX: never checks
  countdown_ = 1;
  started_ = last_check_ = Clock::now();
  deadline_ = max_seconds_ > 0 ? started_ + std::chrono::duration_cast<Clock::duration>(
                                                std::chrono::duration<double>(max_seconds_))
                               : Clock::time_point::max();
}

bool StopCondition::check() {
  if (!reason_.empty()) {
    countdown_ = 1;
    return true;
  }
  if (max_seconds_ == 0 && !requested_) {
    countdown_ = INT64_MAX;
    return false;
  }
  const Clock::time_point now = Clock::now();
  const auto interval = now - last_check_;
  last_check_ = now;
  if (interval < kShortInterval) {
    stride_ = std::min(2 * stride_, kMaxStride);
  } else if (interval > kLongInterval) {
    stride_ = std::max<std::int64_t>(1, stride_ / 2);
  }
  countdown_ = stride_;
  if (now >= deadline_) {
    reason_ = "max_planning_time: the plan was stopped after " + util::show(max_seconds_) + " s";
  } else if (requested_ && requested_()) {
    reason_ = "the plan was stopped on request";
  }
  return !reason_.empty();
}

}  // namespace roomba_rrt::planning
