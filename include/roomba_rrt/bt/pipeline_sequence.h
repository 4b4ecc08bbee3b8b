// PipelineSequence (Nav2): a Sequence that keeps ticking the children it has passed, so an
// earlier child (a replanner) keeps running while a later one (a path follower) acts.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Ticks its children from the first one on every tick, up to the furthest child reached so far
/// (the "pipeline"): earlier children are ticked again each tick even after they succeeded.
///
/// When a child returns
/// - SUCCESS: the next child is ticked in the same tick; after the last child every running
///   child is halted and PipelineSequence returns SUCCESS (the next tick starts over).
/// - FAILURE: every running child is halted and PipelineSequence returns FAILURE (the next tick
///   starts over from the first child).
/// - RUNNING: if it is the furthest child reached, PipelineSequence returns RUNNING; if a later
///   child was reached before, the next child is ticked in the same tick (an earlier stage
///   running, e.g. a plan being recomputed, does not stop a later one).
/// - SKIPPED: as SUCCESS (a run in which every child was skipped returns SKIPPED).
class PipelineSequence final : public ControlNode {
 public:
  using ControlNode::ControlNode;

 private:
  void onEnter() override { furthest_ = 0; }
  Status onTick() override;

  std::size_t furthest_ = 0;  ///< the furthest child ticked in this run
};

}  // namespace roomba_rrt::bt
