// What a key press does to the command roomba_teleop publishes, and what the terminal shows.
#include "roomba_rrt/teleop/keyboard_teleop.h"

#include <gtest/gtest.h>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::teleop {
namespace {

using robot::BumperState;
using robot::Velocity;

std::vector<Key> keys(std::initializer_list<Key> list) { return list; }

TEST(KeyDecoder, reads_letters_both_cases_and_ignores_other_bytes) {
  KeyDecoder decoder;
  EXPECT_EQ(
      decoder.feed("wWsSaAdD xXqQ"),
      keys({Key::kForward, Key::kForward, Key::kBackward, Key::kBackward, Key::kLeft, Key::kLeft,
            Key::kRight, Key::kRight, Key::kStop, Key::kStop, Key::kStop, Key::kQuit, Key::kQuit}));
  EXPECT_TRUE(decoder.feed("hjkl123\n").empty());
}

TEST(KeyDecoder, ctrl_c_and_ctrl_d_quit) {
  KeyDecoder decoder;
  EXPECT_EQ(decoder.feed("\x03\x04"), keys({Key::kQuit, Key::kQuit}));
}

TEST(KeyDecoder, reads_arrow_keys_in_both_cursor_modes) {
  KeyDecoder decoder;
  EXPECT_EQ(decoder.feed("\x1b[A\x1b[B\x1b[C\x1b[D"),
            keys({Key::kForward, Key::kBackward, Key::kRight, Key::kLeft}));
  EXPECT_EQ(decoder.feed("\x1bOA\x1bOD"), keys({Key::kForward, Key::kLeft}));
}

TEST(KeyDecoder, assembles_an_arrow_split_across_reads) {
  KeyDecoder decoder;
  EXPECT_TRUE(decoder.feed("\x1b").empty());
  EXPECT_TRUE(decoder.feed("[").empty());
  EXPECT_EQ(decoder.feed("Aw"), keys({Key::kForward, Key::kForward}));
}

TEST(KeyDecoder, modified_arrows_are_arrows_and_other_sequences_are_dropped) {
  KeyDecoder decoder;
  // Ctrl+Up (ESC [ 1 ; 5 A) is still up; F5 (ESC [ 1 5 ~) is no key, and the w after it counts.
  EXPECT_EQ(decoder.feed("\x1b[1;5A"), keys({Key::kForward}));
  EXPECT_EQ(decoder.feed("\x1b[15~w"), keys({Key::kForward}));
}

TEST(KeyDecoder, a_lone_escape_does_not_swallow_the_next_key) {
  KeyDecoder decoder;
  EXPECT_EQ(decoder.feed("\x1bq"), keys({Key::kQuit}));
}

TEST(ApplyKey, each_press_is_one_step_and_the_command_stays) {
  const TeleopLimits limits;
  Velocity c;
  for (int i = 0; i < 3; ++i) c = applyKey(c, Key::kForward, limits);
  EXPECT_NEAR(c.v, 0.3, 1e-12);
  EXPECT_EQ(c.w, 0);
  c = applyKey(c, Key::kLeft, limits);
  c = applyKey(c, Key::kLeft, limits);
  EXPECT_NEAR(c.v, 0.3, 1e-12);  // turning keeps the speed
  EXPECT_NEAR(c.w, 0.5, 1e-12);
  c = applyKey(c, Key::kRight, limits);
  EXPECT_NEAR(c.w, 0.25, 1e-12);
  c = applyKey(c, Key::kStop, limits);
  EXPECT_EQ(c.v, 0);
  EXPECT_EQ(c.w, 0);
}

TEST(ApplyKey, backwards_past_zero_reverses_and_comes_back_to_exactly_zero) {
  const TeleopLimits limits;
  Velocity c;
  for (int i = 0; i < 7; ++i) c = applyKey(c, Key::kForward, limits);
  for (int i = 0; i < 7; ++i) c = applyKey(c, Key::kBackward, limits);
  EXPECT_EQ(c.v, 0);  // whole steps: no 1e-17 creep left after as many presses back
  c = applyKey(c, Key::kBackward, limits);
  EXPECT_NEAR(c.v, -0.1, 1e-12);
}

TEST(ApplyKey, never_exceeds_the_robots_limits) {
  TeleopLimits limits;
  limits.max_linear_speed = 0.35;
  limits.max_angular_speed = 1.0;
  Velocity c;
  for (int i = 0; i < 20; ++i) {
    c = applyKey(c, Key::kBackward, limits);
    c = applyKey(c, Key::kRight, limits);
  }
  EXPECT_EQ(c.v, -0.35);
  EXPECT_EQ(c.w, -1.0);
  c = applyKey(c, Key::kForward, limits);  // from the limit, one step back towards zero
  EXPECT_NEAR(c.v, -0.3, 1e-12);
}

TEST(ApplyKey, quit_leaves_the_command_to_the_caller) {
  const Velocity c{0.2, -0.5};
  const Velocity after = applyKey(c, Key::kQuit, TeleopLimits{});
  EXPECT_EQ(after.v, 0.2);
  EXPECT_EQ(after.w, -0.5);
}

TEST(Validate, names_the_field_that_cannot_be_used) {
  TeleopLimits limits;
  limits.linear_step = -0.1;
  EXPECT_THROW(
      {
        try {
          validate(limits);
        } catch (const util::InvalidInput& e) {
          EXPECT_EQ(e.field(), "linear_step");
          throw;
        }
      },
      util::InvalidInput);
  limits = TeleopLimits{};
  limits.angular_step = 3;  // more than max_angular_speed (2)
  EXPECT_THROW(validate(limits), util::InvalidInput);
  limits = TeleopLimits{};
  limits.max_linear_speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validate(limits), util::InvalidInput);
  EXPECT_NO_THROW(validate(TeleopLimits{}));
}

TEST(StatusLine, shows_the_command_and_the_bumper) {
  EXPECT_EQ(statusLine({0.3, -0.5}, {}, false),
            "v +0.30 m/s  w -0.50 rad/s  bumper: no bumper message yet");
  EXPECT_EQ(statusLine({0, 0}, {}, true), "v +0.00 m/s  w +0.00 rad/s  bumper: free");
  EXPECT_EQ(statusLine({-0.0, 0}, {true, true, false}, true),
            "v +0.00 m/s  w +0.00 rad/s  bumper: pressed (left)");
  EXPECT_EQ(statusLine({1, 0}, {true, true, true}, true),
            "v +1.00 m/s  w +0.00 rad/s  bumper: pressed (both)");
  EXPECT_EQ(statusLine({1, 0}, {true, false, true}, true),
            "v +1.00 m/s  w +0.00 rad/s  bumper: pressed (right)");
}

TEST(HelpText, names_every_key_and_the_limits) {
  const std::string help = helpText(TeleopLimits{});
  for (const char* word :
       {"w / up", "s / down", "a / left", "d / right", "space", "q / Ctrl-C", "1.00", "2.00"}) {
    EXPECT_NE(help.find(word), std::string::npos) << word;
  }
}

}  // namespace
}  // namespace roomba_rrt::teleop
