// LoopInt, LoopDouble, LoopString and LoopBool (BehaviorTree.CPP 4's LoopNode<T>): run the child
// once for each value of a queue.
#pragma once

#include <deque>
#include <string>

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// A queue of values on a port: a literal "a;b;c" (each read as T reads it) or a blackboard key
/// holding a std::deque<T>.
template <class T>
struct TypeName<std::deque<T>> {
  static std::string get() { return "SharedQueue<" + TypeName<T>::get() + ">"; }
};

template <class T>
struct LiteralParser<std::deque<T>> {
  static constexpr bool kParsable = true;
  static std::string parse(const std::string& text, std::deque<T>& out) {
    out.clear();
    if (text.empty()) return "";
    std::size_t from = 0;
    while (true) {
      const std::size_t to = text.find(';', from);
      T value{};
      const std::string item = text.substr(from, to == std::string::npos ? to : to - from);
      const std::string error = LiteralParser<T>::parse(item, value);
      if (!error.empty()) return "item " + std::to_string(out.size() + 1) + ": " + error;
      out.push_back(std::move(value));
      if (to == std::string::npos) return "";
      from = to + 1;
    }
  }
};

/// When entered, takes the values of `queue`; then on each tick where the child is not running
/// it writes the next value to `value` and ticks the child. The child's RUNNING or SUCCESS (or
/// SKIPPED): RUNNING, the next value on the next tick; FAILURE: FAILURE. With no value left
/// (or none at all) it returns `if_empty` (SUCCESS, FAILURE or SKIPPED) without ticking the
/// child. As BT.CPP's, but a queue on the blackboard is copied, not emptied: the key keeps its
/// values for the next run.
template <class T>
class LoopNode final : public DecoratorNode {
 public:
  static PortList providedPorts() {
    return {inputPort<std::deque<T>>("queue", "the values, one per run of the child: a;b;c"),
            inputPort<std::string>("if_empty",
                                   "what to return with no value left: SUCCESS, FAILURE or SKIPPED",
                                   "SUCCESS"),
            outputPort<T>("value", "the value of this run of the child")};
  }
  LoopNode(std::string name, InputPort<std::deque<T>> queue, Status if_empty, OutputPort<T> value)
      : DecoratorNode(std::move(name)),
        queue_(std::move(queue)),
        if_empty_(if_empty),
        value_(std::move(value)) {}

 private:
  void onEnter() override {
    const std::deque<T>* queue = queue_.get();
    left_ = queue ? *queue : std::deque<T>{};
    child_running_ = false;
  }
  Status onTick() override {
    if (!child_running_) {
      if (left_.empty()) return if_empty_;
      value_.set(left_.front());
      left_.pop_front();
    }
    const Status status = child_->tick();
    child_running_ = status == Status::kRunning;
    return status == Status::kFailure ? Status::kFailure : Status::kRunning;
  }
  void onHalt() override {
    child_->halt();
    child_running_ = false;
  }

  InputPort<std::deque<T>> queue_;
  Status if_empty_;
  OutputPort<T> value_;
  std::deque<T> left_;  ///< the values not yet run
  bool child_running_ = false;
};

}  // namespace roomba_rrt::bt
