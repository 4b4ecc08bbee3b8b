// Test leaves whose statuses are scripted, and that count how they were called.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt::testing {

/// Returns the scripted statuses one per tick (the last one forever) and counts enters, ticks
/// and halts. Tests keep a raw pointer to inspect it after handing ownership to a composite.
class ScriptedLeaf final : public LeafNode {
 public:
  ScriptedLeaf(std::string name, std::vector<Status> script)
      : LeafNode(std::move(name)), script_(script.begin(), script.end()) {}

  void setNext(Status status) { script_.assign(1, status); }

  int enters = 0;
  int ticks = 0;
  int halts = 0;

 private:
  void onEnter() override { ++enters; }
  Status onTick() override {
    ++ticks;
    const Status status = script_.front();
    if (script_.size() > 1) script_.pop_front();
    return status;
  }
  void onHalt() override { ++halts; }

  std::deque<Status> script_;
};

/// Makes a ScriptedLeaf, stores a raw pointer to it in `*out` and returns the owner.
inline std::unique_ptr<ScriptedLeaf> scripted(ScriptedLeaf** out, std::vector<Status> script,
                                              std::string name = "leaf") {
  auto leaf = std::make_unique<ScriptedLeaf>(std::move(name), std::move(script));
  *out = leaf.get();
  return leaf;
}

/// Decorator `Node` (named "decorator", built with `args`) over a scripted leaf reachable
/// through `leaf`.
template <class Node, class... Args>
std::unique_ptr<Node> decorate(ScriptedLeaf** leaf, std::vector<Status> script, Args&&... args) {
  auto node = std::make_unique<Node>("decorator", std::forward<Args>(args)...);
  node->setChild(scripted(leaf, std::move(script)));
  return node;
}

/// A composite of type Node (built with "node" and `args`) over two scripted children.
template <class Node, class... Args>
struct TwoChildren {
  explicit TwoChildren(std::vector<Status> a, std::vector<Status> b, Args... args)
      : node("node", args...) {
    node.addChild(scripted(&first, std::move(a), "first"));
    node.addChild(scripted(&second, std::move(b), "second"));
  }
  Node node;
  ScriptedLeaf* first = nullptr;
  ScriptedLeaf* second = nullptr;
};

constexpr Status S = Status::kSuccess;
constexpr Status F = Status::kFailure;
constexpr Status R = Status::kRunning;
constexpr Status K = Status::kSkipped;

}  // namespace roomba_rrt::bt::testing
