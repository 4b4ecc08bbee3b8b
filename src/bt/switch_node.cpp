#include "roomba_rrt/bt/switch_node.h"

namespace roomba_rrt::bt {

PortList SwitchNode::portsFor(std::size_t cases) {
  PortList ports = {inputPort<std::string>("variable", "the value the cases are compared with")};
  for (std::size_t i = 1; i <= cases; ++i) {
    ports.push_back(inputPort<std::string>("case_" + std::to_string(i),
                                           "the value that selects child " + std::to_string(i)));
  }
  return ports;
}

SwitchNode::SwitchNode(std::string name, InputPort<std::string> variable,
                       std::vector<InputPort<std::string>> cases)
    : ControlNode(std::move(name)), variable_(std::move(variable)), cases_(std::move(cases)) {}

bool SwitchNode::matches(const std::string& variable, const std::string& value) {
  if (variable == value) return true;
  double a = 0;
  double b = 0;
  return LiteralParser<double>::parse(variable, a).empty() &&
         LiteralParser<double>::parse(value, b).empty() && a == b;
}

Status SwitchNode::onTick() {
  std::size_t match = cases_.size();  // the default child
  if (const std::string* variable = variable_.get()) {
    for (std::size_t i = 0; i < cases_.size(); ++i) {
      const std::string* value = cases_[i].get();
      if (value && matches(*variable, *value)) {
        match = i;
        break;
      }
    }
  }
  if (running_ != kNone && running_ != match) children_[running_]->halt();
  const Status status = children_[match]->tick();
  running_ = status == Status::kRunning ? match : kNone;
  return status;
}

}  // namespace roomba_rrt::bt
