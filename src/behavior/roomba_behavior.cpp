#include "roomba_rrt/behavior/roomba_behavior.h"

namespace roomba_rrt::behavior {

namespace {
const std::string kIdle = "Idle";
}

RoombaBehavior::RoombaBehavior(const RoombaParams& params, std::uint32_t seed)
    : params_(params), context_(seed) {
  validate(params_);
  context_.state_name = &kIdle;
  context_.params = &params_;
}

void RoombaBehavior::setParams(const RoombaParams& params) {
  retuneMotions(params_, params, context_);
}

}  // namespace roomba_rrt::behavior
