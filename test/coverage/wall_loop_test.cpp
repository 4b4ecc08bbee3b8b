// The loop along the walls (wall_loop.h): closed, safe, at the planning radius from the walls it
// follows, round the outside of the floor the robot can drive to and not round the furniture
// standing in it; a wall drawn at a slant in a map's steps is followed too.
#include "roomba_rrt/coverage/wall_loop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::coverage {
namespace {

constexpr double kClearance = 0.01;
constexpr double kResolution = 0.025;

/// The lab's empty 6.4 m × 4.8 m room with the 0.17 m Roomba.
world::World emptyRoom() { return world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml"); }

/// A 4 m × 4 m map at 5 cm whose free floor is a diamond (|x − 2| / 1.8 + |y − 2| / 1.4 ≤ 1):
/// four walls at a slant to the lattice, drawn in steps of whole cells.
world::World diamondMap() {
  auto grid = std::make_shared<geometry::OccupancyGrid>();
  grid->width = 80;
  grid->height = 80;
  grid->resolution = 0.05;
  grid->cells.assign(80 * 80, geometry::OccupancyGrid::kOccupied);
  for (int j = 0; j < 80; ++j) {
    for (int i = 0; i < 80; ++i) {
      const double x = (i + 0.5) * 0.05, y = (j + 0.5) * 0.05;
      if (std::fabs(x - 2) / 1.8 + std::fabs(y - 2) / 1.4 <= 1) {
        grid->cells[j * 80 + i] = geometry::OccupancyGrid::kFree;
      }
    }
  }
  world::World world;
  world.room.map = grid;
  world.room.width = 4.0;
  world.room.height = 4.0;
  return world;
}

/// The loop from `from` in `world`'s free space (clearance 1 cm, lattice 2.5 cm).
Polyline loopIn(const world::World& world, const Point2& from) {
  const FreeSpace space(world, kClearance, kResolution);
  const std::optional<int> seed = space.connect(from, FreeSpace::kFree);
  if (!seed) return {};
  return wallLoop(space, *seed);
}

/// The independent check: closed, and every segment sampled every millimetre keeps the robot's
/// radius and the clearance from everything (world::penetrates, what the simulator bumps against).
void expectClosedAndSafe(const world::World& world, const Polyline& loop) {
  ASSERT_GE(loop.size(), 4u);
  EXPECT_EQ(loop.front().x, loop.back().x);
  EXPECT_EQ(loop.front().y, loop.back().y);
  const double planning_radius = world.robot().radius + kClearance;
  for (std::size_t s = 0; s + 1 < loop.size(); ++s) {
    const Point2 a = loop[s], b = loop[s + 1];
    const int samples = 1 + static_cast<int>(std::ceil(geometry::distance(a, b) / 1e-3));
    for (int k = 0; k <= samples; ++k) {
      const double t = double(k) / samples;
      const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
      ASSERT_FALSE(world::penetrates(world, planning_radius - 1e-9, x, y))
          << "segment " << s << " at (" << x << ", " << y << ")";
    }
  }
}

/// The area the closed polyline encloses (m²).
double enclosedArea(const Polyline& loop) {
  double twice = 0;
  for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
    twice += loop[k].x * loop[k + 1].y - loop[k + 1].x * loop[k].y;
  }
  return std::fabs(twice) / 2;
}

TEST(WallLoop, goes_round_the_empty_room_at_the_planning_radius_from_its_walls) {
  const world::World room = emptyRoom();
  const Polyline loop = loopIn(room, {room.robot().initial_pose.x, room.robot().initial_pose.y});
  expectClosedAndSafe(room, loop);
  const double inset = room.robot().radius + kClearance;
  for (const Point2& p : loop) {  // pushed out from the lattice onto the walls' clearance
    EXPECT_TRUE(world::penetrates(room, inset + 1e-3, p.x, p.y)) << p.x << ", " << p.y;
  }
  const double width = room.room.width - 2 * inset, height = room.room.height - 2 * inset;
  EXPECT_NEAR(geometry::pathLength(loop), 2 * (width + height), 0.01 * 2 * (width + height));
  EXPECT_NEAR(enclosedArea(loop), width * height, 0.01 * width * height);
}

TEST(WallLoop, follows_the_steps_of_map_walls_at_a_slant_to_the_lattice) {
  const world::World diamond = diamondMap();
  const Polyline loop = loopIn(diamond, {2.0, 2.0});
  expectClosedAndSafe(diamond, loop);
  // Each corner within a lattice step of a wall (its steps' corners) ...
  const double inset = diamond.robot().radius + kClearance;
  for (const Point2& p : loop) {
    EXPECT_TRUE(world::penetrates(diamond, inset + kResolution, p.x, p.y)) << p.x << ", " << p.y;
  }
  // ... and round all of the floor the robot's centre can take, not cutting across it (the free
  // lattice points' squares, each h × h, reach half a step beyond the outermost points).
  const FreeSpace space(diamond, kClearance, kResolution);
  double free_area = 0;
  for (int k = 0; k < space.size(); ++k) {
    free_area += space.at(k) == FreeSpace::kFree ? kResolution * kResolution : 0;
  }
  const double half_step_band = geometry::pathLength(loop) * kResolution / 2;
  EXPECT_GE(enclosedArea(loop), free_area - half_step_band);
  EXPECT_LE(enclosedArea(loop), free_area + half_step_band);
}

TEST(WallLoop, passes_furniture_standing_free_in_the_room_by) {
  world::World room = emptyRoom();
  room.room.circles.push_back({{3.2, 2.4}, 0.5});  // a round table in the middle
  room.robot().initial_pose = {1.0, 1.0, 0.0};
  const Polyline loop = loopIn(room, {1.0, 1.0});
  expectClosedAndSafe(room, loop);
  for (const Point2& p : loop) {
    EXPECT_GT(geometry::distance(p, {3.2, 2.4}), 0.5 + room.robot().radius + 0.5);
  }
  const Polyline without = loopIn(emptyRoom(), {1.0, 1.0});
  EXPECT_NEAR(geometry::pathLength(loop), geometry::pathLength(without), 1e-9);
}

TEST(WallLoop, none_from_a_point_the_robot_cannot_drive_from) {
  const world::World room = emptyRoom();
  const FreeSpace space(room, kClearance, kResolution);
  EXPECT_TRUE(wallLoop(space, space.index(0, 0)).empty());  // the corner: too close to the walls
  EXPECT_TRUE(wallLoop(space, -1).empty());
  EXPECT_TRUE(wallLoop(space, space.size()).empty());
}

}  // namespace
}  // namespace roomba_rrt::coverage
