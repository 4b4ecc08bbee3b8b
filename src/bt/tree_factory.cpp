// The node registry of TreeFactory (BehaviorTree.CPP's bt_factory): node types, their kinds,
// builders and ports, and the built-in control nodes and decorators. Reading tree files is
// xml_parsing.cpp.
#include "roomba_rrt/bt/tree_factory.h"

#include <cmath>
#include <iostream>

#include "roomba_rrt/bt/always_status.h"
#include "roomba_rrt/bt/blackboard_nodes.h"
#include "roomba_rrt/bt/delay_node.h"
#include "roomba_rrt/bt/entry_updated.h"
#include "roomba_rrt/bt/force_status.h"
#include "roomba_rrt/bt/if_then_else_node.h"
#include "roomba_rrt/bt/inverter_node.h"
#include "roomba_rrt/bt/keep_running_until_failure.h"
#include "roomba_rrt/bt/loop_node.h"
#include "roomba_rrt/bt/parallel_all_node.h"
#include "roomba_rrt/bt/parallel_node.h"
#include "roomba_rrt/bt/pipeline_sequence.h"
#include "roomba_rrt/bt/precondition_node.h"
#include "roomba_rrt/bt/rate_controller.h"
#include "roomba_rrt/bt/reactive_selector.h"
#include "roomba_rrt/bt/reactive_sequence.h"
#include "roomba_rrt/bt/recovery_node.h"
#include "roomba_rrt/bt/repeat_node.h"
#include "roomba_rrt/bt/retry_node.h"
#include "roomba_rrt/bt/run_once_node.h"
#include "roomba_rrt/bt/script_node.h"
#include "roomba_rrt/bt/selector_node.h"
#include "roomba_rrt/bt/sequence_node.h"
#include "roomba_rrt/bt/sequence_with_memory.h"
#include "roomba_rrt/bt/sleep_node.h"
#include "roomba_rrt/bt/switch_node.h"
#include "roomba_rrt/bt/timeout_node.h"
#include "roomba_rrt/bt/try_catch_node.h"
#include "roomba_rrt/bt/while_do_else_node.h"

namespace roomba_rrt::bt {
namespace {

/// A builder for node types whose only argument is the instance name.
template <class Node>
TreeFactory::Builder namedBuilder() {
  return [](const NodeSpec& spec) { return std::make_unique<Node>(spec.name); };
}

/// `if_empty` of a Loop node: SUCCESS, FAILURE or SKIPPED.
Status loopIfEmpty(const NodeSpec& spec) {
  const std::string text = spec.literal<std::string>("if_empty");
  if (text == "SUCCESS") return Status::kSuccess;
  if (text == "FAILURE") return Status::kFailure;
  if (text == "SKIPPED") return Status::kSkipped;
  throw std::invalid_argument("port 'if_empty' must be SUCCESS, FAILURE or SKIPPED, got '" + text +
                              "'");
}

/// Milliseconds as ticks at the tree's tick rate: 0 stays 0 (Delay and Sleep: at once).
long ticksOf(const NodeSpec& spec, const std::string& port) {
  const long msec = spec.literal<long>(port);
  return msec == 0 ? 0 : TimeoutNode::ticksFor(msec, spec.tick_rate);
}

}  // namespace

const std::string& NodeSpec::text(const std::string& port) const {
  const auto it = attributes.find(port);
  if (it == attributes.end()) throw std::invalid_argument("missing port '" + port + "'");
  return it->second;
}

Blackboard& NodeSpec::board() const {
  if (!blackboard) throw std::invalid_argument("the node was built without a blackboard");
  return *blackboard;
}

TreeFactory::TreeFactory()
    : notice_([](const std::string& text) { std::cerr << "roomba_rrt: " << text << '\n'; }) {
  registerNode("Sequence", NodeKind::kControl, namedBuilder<SequenceNode>());
  registerNode("SequenceWithMemory", NodeKind::kControl, namedBuilder<SequenceWithMemory>());
  registerNode("Fallback", NodeKind::kControl, namedBuilder<SelectorNode>());
  registerNode("ReactiveSequence", NodeKind::kControl, namedBuilder<ReactiveSequence>());
  registerNode("ReactiveFallback", NodeKind::kControl, namedBuilder<ReactiveSelector>());
  registerNode("PipelineSequence", NodeKind::kControl, namedBuilder<PipelineSequence>());
  registerNodeType<RecoveryNode>("RecoveryNode", [](const NodeSpec& s) {
    return std::make_unique<RecoveryNode>(s.name, s.literal<int>("number_of_retries"));
  });
  registerNode("Inverter", NodeKind::kDecorator, namedBuilder<InverterNode>());
  registerNodeType<RepeatNode>("Repeat", [](const NodeSpec& s) {
    return std::make_unique<RepeatNode>(s.name, s.literal<int>("num_cycles"));
  });
  registerNodeType<RetryNode>("RetryUntilSuccessful", [](const NodeSpec& s) {
    return std::make_unique<RetryNode>(s.name, s.literal<int>("num_attempts"));
  });
  registerNodeType<TimeoutNode>("Timeout", [](const NodeSpec& s) {
    const long msec = s.literal<long>("msec");
    const long ticks = s.literal<long>("ticks");
    if ((msec > 0) == (ticks > 0)) {
      throw std::invalid_argument("give either msec (BehaviorTree.CPP v4) or ticks, not " +
                                  std::string(msec > 0 ? "both" : "neither"));
    }
    return std::make_unique<TimeoutNode>(
        s.name, ticks > 0 ? ticks : TimeoutNode::ticksFor(msec, s.tick_rate));
  });
  registerNodeType<RateController>("RateController", [](const NodeSpec& s) {
    return std::make_unique<RateController>(s.name, s.literal<double>("hz"), s.tick_rate,
                                            *s.blackboard);
  });
  registerStandardNodes();
}

void TreeFactory::registerStandardNodes() {
  registerNode("AlwaysSuccess", NodeKind::kLeaf, namedBuilder<AlwaysSuccess>());
  registerNode("AlwaysFailure", NodeKind::kLeaf, namedBuilder<AlwaysFailure>());
  registerNodeType<SleepNode>("Sleep", [](const NodeSpec& s) {
    return std::make_unique<SleepNode>(s.name, ticksOf(s, "msec"), *s.blackboard);
  });
  registerNode("ForceSuccess", NodeKind::kDecorator, namedBuilder<ForceSuccess>());
  registerNode("ForceFailure", NodeKind::kDecorator, namedBuilder<ForceFailure>());
  registerNode("KeepRunningUntilFailure", NodeKind::kDecorator,
               namedBuilder<KeepRunningUntilFailure>());
  registerNodeType<DelayNode>("Delay", [](const NodeSpec& s) {
    return std::make_unique<DelayNode>(s.name, ticksOf(s, "delay_msec"), *s.blackboard);
  });
  registerNodeType<ParallelNode>("Parallel", [](const NodeSpec& s) {
    return std::make_unique<ParallelNode>(s.name, s.literal<int>("success_count"),
                                          s.literal<int>("failure_count"));
  });
  registerNodeType<ParallelAllNode>("ParallelAll", [](const NodeSpec& s) {
    return std::make_unique<ParallelAllNode>(s.name, s.literal<int>("max_failures"));
  });
  const auto loop = [this](const std::string& type, auto value) {
    using T = decltype(value);
    registerNodeType<LoopNode<T>>(type, [](const NodeSpec& s) {
      return std::make_unique<LoopNode<T>>(s.name, s.input<std::deque<T>>("queue"), loopIfEmpty(s),
                                           s.output<T>("value"));
    });
  };
  loop("LoopInt", int{});
  loop("LoopDouble", double{});
  loop("LoopString", std::string{});
  loop("LoopBool", bool{});
  registerNodeType<RunOnceNode>("RunOnce", [](const NodeSpec& s) {
    return std::make_unique<RunOnceNode>(s.name, s.literal<bool>("then_skip"));
  });
  registerNode("AsyncSequence", NodeKind::kControl,
               [](const NodeSpec& s) { return std::make_unique<SequenceNode>(s.name, true); });
  registerNode("AsyncFallback", NodeKind::kControl,
               [](const NodeSpec& s) { return std::make_unique<SelectorNode>(s.name, true); });
  registerNodeType<TryCatchNode>("TryCatch", [](const NodeSpec& s) {
    return std::make_unique<TryCatchNode>(s.name, s.literal<bool>("catch_on_halt"));
  });
  registerNode("IfThenElse", NodeKind::kControl, namedBuilder<IfThenElseNode>());
  registerNode("WhileDoElse", NodeKind::kControl, namedBuilder<WhileDoElseNode>());
  registerNodeType<ScriptNode>("Script", [](const NodeSpec& s) {
    return std::make_unique<ScriptNode>(s.name, s.script("code"), *s.blackboard);
  });
  registerNodeType<ScriptCondition>("ScriptCondition", [](const NodeSpec& s) {
    return std::make_unique<ScriptCondition>(s.name, s.script("code"), *s.blackboard);
  });
  registerNodeType<PreconditionNode>("Precondition", [](const NodeSpec& s) {
    const std::string otherwise = s.literal<std::string>("else");
    const std::map<std::string, Status> statuses = {{"SUCCESS", Status::kSuccess},
                                                    {"FAILURE", Status::kFailure},
                                                    {"RUNNING", Status::kRunning},
                                                    {"SKIPPED", Status::kSkipped}};
    if (statuses.count(otherwise) == 0) {
      throw std::invalid_argument(
          "port 'else' must be SUCCESS, FAILURE, RUNNING or SKIPPED, got '" + otherwise + "'");
    }
    return std::make_unique<PreconditionNode>(s.name, s.script("if"), statuses.at(otherwise),
                                              *s.blackboard);
  });
  // Their keys are named, not bound: any type scripts know, so plain attributes.
  registerNode("SetBlackboard", NodeKind::kLeaf,
               [](const NodeSpec& s) {
                 std::string source;
                 const bool copy = parseBlackboardKey(s.literal<std::string>("value"), source);
                 return std::make_unique<SetBlackboard>(
                     s.name, s.keyName("output_key"),
                     copy ? std::optional<std::string>(source) : std::nullopt,
                     s.literal<std::string>("value"), *s.blackboard);
               },
               {"value", "output_key"});
  registerNode("UnsetBlackboard", NodeKind::kLeaf,
               [](const NodeSpec& s) {
                 return std::make_unique<UnsetBlackboard>(s.name, s.keyName("key"), *s.blackboard);
               },
               {"key"});
  registerNode("WasEntryUpdated", NodeKind::kCondition,
               [](const NodeSpec& s) {
                 return std::make_unique<WasEntryUpdated>(s.name, s.keyName("entry"),
                                                          *s.blackboard);
               },
               {"entry"});
  for (const auto& [type, otherwise] :
       {std::pair<const char*, Status>{"SkipUnlessUpdated", Status::kSkipped},
        {"WaitValueUpdate", Status::kRunning}}) {
    registerNode(type, NodeKind::kDecorator,
                 [otherwise = otherwise](const NodeSpec& s) {
                   return std::make_unique<EntryUpdatedDecorator>(s.name, s.keyName("entry"),
                                                                  *s.blackboard, otherwise);
                 },
                 {"entry"});
  }
  for (std::size_t cases = 2; cases <= 6; ++cases) {
    registerNodeWithPorts(
        "Switch" + std::to_string(cases), NodeKind::kControl,
        [cases](const NodeSpec& s) {
          std::vector<InputPort<std::string>> values;
          for (std::size_t i = 1; i <= cases; ++i) {
            values.push_back(s.input<std::string>("case_" + std::to_string(i)));
          }
          return std::make_unique<SwitchNode>(s.name, s.input<std::string>("variable"),
                                              std::move(values));
        },
        SwitchNode::portsFor(cases));
  }
}

void TreeFactory::registerNode(const std::string& type, NodeKind kind, Builder builder,
                               std::vector<std::string> attributes) {
  PortList ports;
  for (auto& name : attributes) {
    PortInfo port;
    port.name = std::move(name);
    port.type_name = "string";
    port.default_value = std::nullopt;
    port.raw = true;
    ports.push_back(std::move(port));
  }
  registerNodeWithPorts(type, kind, std::move(builder), std::move(ports));
}

void TreeFactory::registerNodeWithPorts(const std::string& type, NodeKind kind, Builder builder,
                                        PortList ports) {
  if (!builder) throw std::invalid_argument("node type '" + type + "' has no builder");
  for (const PortInfo& port : ports) {
    if (port.name.empty() || port.name == "name") {
      throw std::invalid_argument("node type '" + type + "': invalid port name '" + port.name +
                                  "'");
    }
    if (!port.raw && (!port.declare || !port.check)) {
      throw std::invalid_argument("node type '" + type + "': port '" + port.name +
                                  "' was not made by inputPort() or outputPort()");
    }
  }
  if (!entries_.emplace(type, Entry{kind, std::move(builder), std::move(ports)}).second) {
    throw std::invalid_argument("node type '" + type + "' is already registered");
  }
}

void TreeFactory::registerLeaf(const std::string& type, Builder builder) {
  registerNode(type, NodeKind::kLeaf, std::move(builder));
}

void TreeFactory::setTickRate(double hz) {
  if (!(std::isfinite(hz) && hz > 0)) {
    throw util::InvalidInput("tick_rate", "must be finite and > 0, got " + util::show(hz));
  }
  tick_rate_ = hz;
}

const PortList& TreeFactory::ports(const std::string& type) const {
  const auto it = entries_.find(type);
  if (it == entries_.end()) throw std::invalid_argument("unknown node type '" + type + "'");
  return it->second.ports;
}

std::vector<std::string> TreeFactory::registeredTypes() const {
  std::vector<std::string> types;
  for (const auto& entry : entries_) types.push_back(entry.first);
  return types;
}

void TreeFactory::notice(const std::string& text) const {
  if (notice_) notice_(text);
}

}  // namespace roomba_rrt::bt
