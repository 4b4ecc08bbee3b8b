// The small conversions every node shares (src/ros/message_parts.h).
#include "../../src/ros/message_parts.h"

#include <gtest/gtest.h>

namespace roomba_rrt::nodes {
namespace {

// Issue 44, item 5: "/map" reached tf2, which printed some ten warnings per request.
TEST(MessageParts, a_frame_id_with_leading_slashes_is_the_frame_tf2_knows) {
  EXPECT_EQ(tfFrameId("/map"), "map");
  EXPECT_EQ(tfFrameId("//odom"), "odom");
  EXPECT_EQ(tfFrameId("map"), "map");
  EXPECT_EQ(tfFrameId("/robot_a/base_link"), "robot_a/base_link");
  EXPECT_EQ(tfFrameId("/"), "");
  EXPECT_EQ(tfFrameId(""), "");
}

}  // namespace
}  // namespace roomba_rrt::nodes
