#include "roomba_rrt/bt/status.h"

#include <stdexcept>
#include <string>

namespace roomba_rrt::bt {

const char* toString(Status status) {
  switch (status) {
    case Status::kSuccess:
      return "SUCCESS";
    case Status::kFailure:
      return "FAILURE";
    case Status::kRunning:
      return "RUNNING";
    case Status::kSkipped:
      return "SKIPPED";
  }
  return "INVALID";
}

void throwImpossibleStatus(const char* node, Status status) {
  throw std::logic_error(std::string(node) + " received an impossible child status (" +
                         std::to_string(static_cast<int>(status)) + ")");
}

}  // namespace roomba_rrt::bt
