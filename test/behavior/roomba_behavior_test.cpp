// The lab's tick rules, checked on both the FSM and the BT (typed tests): each transition at the
// right tick, the spiral's ω, GoBack's 5 cm, Rotate's exact angle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "roomba_rrt/behavior/motion_primitives.h"
#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::behavior {
namespace {

constexpr double kDt = 1.0 / 60.0;
const robot::BumperState kFree{};
const robot::BumperState kBump{true, true, true};

template <class Behavior>
class RoombaBehaviorTest : public ::testing::Test {
 protected:
  Behavior roomba{RoombaParams{}, 7};

  /// Ticks with the bumper released `n` times.
  void run(int n) {
    for (int i = 0; i < n; ++i) roomba.tick(kFree);
  }
  /// Ticks into GoBack: 10 ticks forward, then a bump; returns the bump tick's command.
  robot::Velocity bumpAfterTenTicks() {
    run(10);
    return roomba.tick(kBump);
  }
};

using Behaviors = ::testing::Types<RoombaFsm, RoombaBt>;
TYPED_TEST_SUITE(RoombaBehaviorTest, Behaviors);

TYPED_TEST(RoombaBehaviorTest, starts_moving_forward_at_forward_speed) {
  const robot::Velocity cmd = this->roomba.tick(kFree);
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveForward);
  EXPECT_EQ(this->roomba.stateName(), "MoveForward");
  EXPECT_EQ(cmd.v, 0.5);
  EXPECT_EQ(cmd.w, 0.0);
}

TYPED_TEST(RoombaBehaviorTest, forward_turns_into_spiral_after_180_ticks) {
  this->run(180);
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveForward);
  const robot::Velocity cmd = this->roomba.tick(kFree);
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveInSpiral);
  EXPECT_DOUBLE_EQ(cmd.w, 0.5 / 0.2);  // the spiral's first tick (k = 0) runs in the same tick
}

TYPED_TEST(RoombaBehaviorTest, spiral_omega_at_k_600_is_0_5_over_0_7) {
  this->run(180 + 600);
  const robot::Velocity cmd = this->roomba.tick(kFree);  // the spiral's tick k = 600
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveInSpiral);
  EXPECT_DOUBLE_EQ(cmd.v, 0.5);
  EXPECT_NEAR(cmd.w, 0.5 / 0.7, 1e-12);
}

TYPED_TEST(RoombaBehaviorTest, spiral_lasts_1200_ticks) {
  this->run(180 + 1200);
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveInSpiral);
  this->run(2);  // the BT may spend one idle tick here
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveForward);
}

TYPED_TEST(RoombaBehaviorTest, a_bump_during_the_spiral_enters_go_back_in_the_same_tick) {
  this->run(180 + 50);
  const robot::Velocity cmd = this->roomba.tick(kBump);
  EXPECT_EQ(this->roomba.state(), RoombaState::kGoBack);
  EXPECT_EQ(cmd.v, -0.1);
  EXPECT_EQ(cmd.w, 0.0);
}

TYPED_TEST(RoombaBehaviorTest, a_bump_has_priority_over_the_timer) {
  this->run(180);  // MoveForward's time is up on the next tick
  this->roomba.tick(kBump);
  EXPECT_EQ(this->roomba.state(), RoombaState::kGoBack);
}

TYPED_TEST(RoombaBehaviorTest, go_back_lasts_30_ticks_and_moves_5_cm) {
  double travelled = this->bumpAfterTenTicks().v * kDt;  // GoBack's first tick
  for (int i = 1; i < 30; ++i) {
    const robot::Velocity cmd = this->roomba.tick(kBump);  // the bumper is ignored in GoBack
    ASSERT_EQ(this->roomba.state(), RoombaState::kGoBack) << "tick " << i;
    travelled += cmd.v * kDt;
  }
  EXPECT_NEAR(travelled, -0.05, 1e-12);
  this->roomba.tick(kBump);
  EXPECT_EQ(this->roomba.state(), RoombaState::kRotate);
}

TYPED_TEST(RoombaBehaviorTest, rotate_turns_exactly_the_drawn_angle_then_moves_forward) {
  // The angle the behaviour draws: the first draw of its generator (seed 7).
  std::mt19937 rng(7);
  const double angle = Rotate::drawAngle(rng);
  const long ticks = static_cast<long>(std::ceil(std::fabs(angle) / (0.5 * kDt)));

  this->bumpAfterTenTicks();
  this->run(29);
  double turned = 0;
  for (long i = 0; i < ticks; ++i) {
    const robot::Velocity cmd = this->roomba.tick(kBump);  // the bumper is ignored in Rotate
    ASSERT_EQ(this->roomba.state(), RoombaState::kRotate) << "tick " << i;
    EXPECT_EQ(cmd.v, 0.0);
    EXPECT_LE(std::fabs(cmd.w), 0.5);
    turned += cmd.w * kDt;
  }
  EXPECT_NEAR(turned, angle, 1e-12);
  this->run(2);  // the BT may spend one idle tick here
  EXPECT_EQ(this->roomba.state(), RoombaState::kMoveForward);
}

TYPED_TEST(RoombaBehaviorTest, the_same_seed_reproduces_the_run_and_another_seed_does_not) {
  TypeParam a(RoombaParams{}, 3), b(RoombaParams{}, 3), c(RoombaParams{}, 4);
  bool all_equal = true, other_differs = false;
  for (int i = 0; i < 20000; ++i) {
    const robot::BumperState bumper = i % 700 == 650 ? kBump : kFree;
    const robot::Velocity va = a.tick(bumper), vb = b.tick(bumper), vc = c.tick(bumper);
    all_equal = all_equal && va.v == vb.v && va.w == vb.w;
    other_differs = other_differs || va.w != vc.w;
  }
  EXPECT_TRUE(all_equal);
  EXPECT_TRUE(other_differs);
}

// dynamic_reconfigure's rule: new constants reach a motion when it starts, never mid-motion.
TYPED_TEST(RoombaBehaviorTest, new_params_take_effect_when_the_next_motion_starts) {
  this->run(10);  // in MoveForward at 0.5 m/s
  RoombaParams tuned;
  tuned.forward_speed = 0.3;
  tuned.go_back_time = 1.0;  // 60 ticks instead of 30
  this->roomba.setParams(tuned);
  EXPECT_EQ(this->roomba.tick(kFree).v, 0.5);  // the running MoveForward keeps its speed
  const robot::Velocity back = this->roomba.tick(kBump);
  EXPECT_EQ(this->roomba.state(), RoombaState::kGoBack);
  EXPECT_EQ(back.v, -0.1);
  int go_back_ticks = 1;
  while (this->roomba.tick(kFree), this->roomba.state() == RoombaState::kGoBack) ++go_back_ticks;
  EXPECT_EQ(go_back_ticks, 60);  // the GoBack that started after the change lasts 1 s
  while (this->roomba.state() != RoombaState::kMoveForward) this->roomba.tick(kFree);
  EXPECT_EQ(this->roomba.tick(kFree).v, 0.3);  // the next MoveForward drives at the new speed
}

TYPED_TEST(RoombaBehaviorTest, invalid_new_params_are_refused_and_change_nothing) {
  RoombaParams bad;
  bad.forward_speed = 0;  // must be > 0
  EXPECT_THROW(this->roomba.setParams(bad), util::InvalidInput);
  bad = RoombaParams{};
  bad.rate = 5;  // the sample time is the node's: ignored, not an error
  this->roomba.setParams(bad);
  EXPECT_EQ(this->roomba.params().rate, 60.0);
  EXPECT_EQ(this->roomba.params().forward_speed, 0.5);
  EXPECT_EQ(this->roomba.tick(kFree).v, 0.5);
}

}  // namespace
}  // namespace roomba_rrt::behavior
