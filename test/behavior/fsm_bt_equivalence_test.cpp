// The FSM and the BT are the same behaviour: over 10 minutes of ticks they command the same
// (v, ω) sequence, apart from the BT's idle ticks (see RoombaBt for the rule).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"

namespace roomba_rrt::behavior {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr int kTenMinutes = 10 * 60 * 60;

/// A one-dimensional room that answers the behaviour's commands: the robot advances along a line
/// (s += v·Δt, spiral included) towards a wall; the bumper is pressed while s ≥ wall. Each
/// rotation puts a new wall 0.3–14 m ahead (drawn from the room's own generator), so the
/// behaviour bumps during MoveForward and MoveInSpiral, and some spirals run to their end.
/// A tick commanding (0, 0) changes nothing, so the BT's idle tick does not consume a reading.
class LineRoom {
 public:
  explicit LineRoom(unsigned seed) : rng_(seed) {}
  robot::BumperState sense() const { return {s_ >= wall_, s_ >= wall_, s_ >= wall_}; }
  void move(const robot::Velocity& cmd) {
    s_ += cmd.v * kDt;
    const bool rotating = cmd.v == 0 && cmd.w != 0;
    if (rotating && !rotating_) wall_ = s_ + std::uniform_real_distribution<>(0.3, 14.0)(rng_);
    rotating_ = rotating;
  }

 private:
  std::mt19937 rng_;
  double s_ = 0;
  double wall_ = 2.0;
  bool rotating_ = false;
};

struct Step {
  double v, w;
  RoombaState state;
};

TEST(FsmBtEquivalence, same_commands_for_ten_minutes_apart_from_the_bt_idle_ticks) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    RoombaFsm fsm(RoombaParams{}, seed);
    LineRoom fsm_room(100 + seed);
    std::vector<Step> expected;
    int go_backs = 0, root_completions = 0, spirals_completed = 0;
    RoombaState previous = RoombaState::kMoveForward;
    for (int i = 0; i < kTenMinutes; ++i) {
      const robot::Velocity cmd = fsm.tick(fsm_room.sense());
      fsm_room.move(cmd);
      expected.push_back({cmd.v, cmd.w, fsm.state()});
      if (fsm.state() == RoombaState::kGoBack && previous != RoombaState::kGoBack) ++go_backs;
      if (fsm.state() == RoombaState::kMoveForward &&
          (previous == RoombaState::kMoveInSpiral || previous == RoombaState::kRotate)) {
        ++root_completions;
        if (previous == RoombaState::kMoveInSpiral) ++spirals_completed;
      }
      previous = fsm.state();
    }
    ASSERT_GT(go_backs, 10) << "the room must make the robot bump";
    ASSERT_GT(spirals_completed, 0) << "some spirals must run to their end";

    RoombaBt bt(RoombaParams{}, seed);
    LineRoom bt_room(100 + seed);
    int idle_ticks = 0;
    std::size_t compared = 0;
    while (compared < expected.size()) {
      const robot::Velocity cmd = bt.tick(bt_room.sense());
      bt_room.move(cmd);
      if (bt.lastTickIdle()) {
        ++idle_ticks;
        ASSERT_LT(idle_ticks, kTenMinutes) << "the BT never moves";
        continue;
      }
      const Step& want = expected[compared];
      ASSERT_EQ(cmd.v, want.v) << "seed " << seed << ", FSM tick " << compared;
      ASSERT_EQ(cmd.w, want.w) << "seed " << seed << ", FSM tick " << compared;
      ASSERT_EQ(bt.state(), want.state) << "seed " << seed << ", FSM tick " << compared;
      ++compared;
    }
    EXPECT_EQ(idle_ticks, root_completions) << "seed " << seed << ": one idle tick per completion";
  }
}

}  // namespace
}  // namespace roomba_rrt::behavior
