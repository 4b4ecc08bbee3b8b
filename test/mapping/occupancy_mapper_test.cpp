// The mapper (occupancy_mapper.h) against the true world: scans cast exactly by the simulator's
// ray caster from scripted poses, in a map world (where a map aligned with the world's cells must
// come out cell for cell) and in the furnished room; the exact grid walk against a brute-force
// oracle; +inf rays; scans that must be refused; the bumper's marks; a map that grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "roomba_rrt/mapping/map_accuracy.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/mapping/sensor_scan.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::mapping {
namespace {

using geometry::OccupancyGrid;
constexpr float kInf = std::numeric_limits<float>::infinity();

/// A scan of the LDS preset (360 rays, 0.12–3.5 m) taken at `pose` in `world`.
std::vector<float> ldsScan(const world::World& world, const robot::Pose2D& pose,
                           const sensors::RangeSensorSpec& lds = sensors::ldsPreset()) {
  static std::mt19937 noise;
  const sensors::RayCaster caster(world.room);
  std::vector<float> ranges;
  sensors::measure(caster, lds, sensors::RayFan(lds), pose, {}, noise, ranges);
  return ranges;
}

/// Scans from a lattice of free poses over the room (every 0.4 m, at two headings).
void mapRoom(const world::World& world, OccupancyMapper& mapper) {
  const sensors::RangeSensorSpec lds = sensors::ldsPreset();
  const world::Room& room = world.room;
  for (double y = room.origin.y + 0.2; y < room.origin.y + room.height; y += 0.4) {
    for (double x = room.origin.x + 0.2; x < room.origin.x + room.width; x += 0.4) {
      if (world::penetrates(world, 0.17, x, y)) continue;
      for (double theta : {0.1, 1.7}) {
        const robot::Pose2D pose{x, y, theta};
        const std::vector<float> ranges = ldsScan(world, pose, lds);
        ASSERT_EQ(mapper.addScan(pose, scanView(lds, ranges)), "");
      }
    }
  }
}

/// A 4 × 3 m map world of 0.05 m cells: walls round it, a pillar and a wall with a door.
world::World mapWorld() {
  auto g = std::make_shared<OccupancyGrid>();
  g->width = 80;
  g->height = 60;
  g->resolution = 0.05;
  g->origin = {-1.0, -0.5};
  g->cells.assign(80 * 60, OccupancyGrid::kFree);
  for (int j = 0; j < 60; ++j) {
    for (int i = 0; i < 80; ++i) {
      const bool border = i == 0 || j == 0 || i == 79 || j == 59;
      const bool pillar = i >= 20 && i < 24 && j >= 20 && j < 26;
      const bool wall = i == 50 && (j < 25 || j > 34);
      if (border || pillar || wall) g->cells[j * 80 + i] = OccupancyGrid::kOccupied;
    }
  }
  world::World world;
  world::useMap(world, g, "");
  return world;
}

MapperOptions optionsFor(const world::World& world) {
  MapperOptions o;
  o.resolution = 0.05;
  o.xmin = world.room.origin.x;
  o.ymin = world.room.origin.y;
  o.xmax = o.xmin + world.room.width;
  o.ymax = o.ymin + world.room.height;
  return o;
}

TEST(OccupancyMapper, MapOfAMapWorldAlignedWithItsCellsIsTheWorldCellForCell) {
  const world::World world = mapWorld();
  OccupancyMapper mapper(optionsFor(world));
  mapRoom(world, mapper);
  const OccupancyGrid map = mapper.grid();
  const OccupancyGrid& truth = *world.room.map;
  ASSERT_EQ(map.width, truth.width);
  ASSERT_EQ(map.height, truth.height);
  int known = 0, wrong = 0;
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      if (map.at(i, j) == OccupancyGrid::kUnknown) continue;
      ++known;
      if (map.at(i, j) != truth.at(i, j)) {
        ++wrong;
        ADD_FAILURE() << "cell " << i << ", " << j << ": " << int(map.at(i, j)) << " log-odds "
                      << mapper.logOdds(i, j);
      }
    }
  }
  EXPECT_EQ(wrong, 0) << "of " << known << " known cells";
  EXPECT_GT(known, 0.9 * map.width * map.height);  // the walls' far sides stay unknown
  // The door in the inner wall is free, the pillar occupied.
  EXPECT_EQ(map.at(50, 30), OccupancyGrid::kFree);
  EXPECT_EQ(map.at(20, 22), OccupancyGrid::kOccupied);
}

TEST(OccupancyMapper, FurnishedRoomAgreesWithTheTruthAndNoWallIsMoreThanOneCellOff) {
  const world::World world = world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  OccupancyMapper mapper(optionsFor(world));
  mapRoom(world, mapper);
  const MapAccuracy a = compare(mapper.grid(), world);
  EXPECT_GE(a.agreement(), 0.99) << a.agreeing << " of " << a.known;
  EXPECT_EQ(a.walls_off, 0u);
  EXPECT_GT(a.occupied, 100u);
  EXPECT_GT(a.free_known, 5000u);
}

/// The cells whose open squares the segment from a to b (in cells) passes through.
std::set<std::pair<int, int>> bruteCells(double ax, double ay, double bx, double by) {
  std::set<std::pair<int, int>> cells;
  for (int j = static_cast<int>(std::floor(std::min(ay, by))) - 1; j <= std::max(ay, by) + 1; ++j) {
    for (int i = static_cast<int>(std::floor(std::min(ax, bx))) - 1; i <= std::max(ax, bx) + 1;
         ++i) {
      // Liang–Barsky against the square: a piece of positive length inside.
      double t0 = 0, t1 = 1;
      const double d[4] = {-(bx - ax), bx - ax, -(by - ay), by - ay};
      const double q[4] = {ax - i, i + 1 - ax, ay - j, j + 1 - ay};
      bool in = true;
      for (int k = 0; k < 4 && in; ++k) {
        if (d[k] == 0) {
          in = q[k] > 0;
        } else if (d[k] < 0) {
          t0 = std::max(t0, q[k] / d[k]);
        } else {
          t1 = std::min(t1, q[k] / d[k]);
        }
      }
      if (in && t1 - t0 > 1e-12) cells.insert({i, j});
    }
  }
  return cells;
}

TEST(OccupancyMapper, EveryRayMarksExactlyTheCellsItCrosses) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int n = 0; n < 2000; ++n) {
    MapperOptions o;
    o.resolution = 0.1;
    o.xmin = o.ymin = 0;
    o.xmax = o.ymax = 4;
    OccupancyMapper mapper(o);
    const robot::Pose2D pose{0.5 + 3 * u(rng), 0.5 + 3 * u(rng), 0};
    const float range = static_cast<float>(0.01 + 1.2 * u(rng));
    const double angle = 2 * M_PI * u(rng);
    const ScanView scan{angle, angle, 0, 0, 5, &range, 1};
    ASSERT_EQ(mapper.addScan(pose, scan), "");
    // In the cells of the map as it is now (it grows when the ray leaves it).
    const double ax = (pose.x - mapper.origin().x) / 0.1, ay = (pose.y - mapper.origin().y) / 0.1;
    const double bx = ax + range * std::cos(angle) / 0.1, by = ay + range * std::sin(angle) / 0.1;
    const std::set<std::pair<int, int>> expected = bruteCells(ax, ay, bx, by);
    std::set<std::pair<int, int>> marked;
    for (int j = 0; j < mapper.height(); ++j) {
      for (int i = 0; i < mapper.width(); ++i) {
        if (mapper.observed(i, j)) marked.insert({i, j});
      }
    }
    ASSERT_EQ(marked, expected) << "ray " << n;
    // The cell of the end is the hit, every other one free.
    const int ie = static_cast<int>(std::floor(bx)), je = static_cast<int>(std::floor(by));
    for (const auto& [i, j] : marked) {
      EXPECT_EQ(mapper.logOdds(i, j) > 0, i == ie && j == je) << "ray " << n;
    }
  }
}

TEST(OccupancyMapper, NoReturnIsFreeSpaceUpToRangeMax) {
  MapperOptions o;
  OccupancyMapper mapper(o);
  const std::vector<float> ranges(4, kInf);
  // Four rays along +x, +y, −x, −y, 2 m long.
  const ScanView scan{0, 1.5 * M_PI, M_PI / 2, 0.1, 2.0, ranges.data(), ranges.size()};
  ASSERT_EQ(mapper.addScan({0.02, 0.02, 0}, scan), "");
  const OccupancyGrid map = mapper.grid();
  EXPECT_EQ(map.at(map.column(1.97), map.row(0.02)), OccupancyGrid::kFree);
  EXPECT_EQ(map.at(map.column(0.02), map.row(-1.97)), OccupancyGrid::kFree);
  EXPECT_EQ(map.at(map.column(2.08), map.row(0.02)), OccupancyGrid::kUnknown);
  for (std::int8_t v : map.cells) EXPECT_NE(v, OccupancyGrid::kOccupied);
}

TEST(OccupancyMapper, RaysOfNoMeaningAreSkippedAndNeverMakeNaN) {
  OccupancyMapper mapper(MapperOptions{});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> ranges = {nan, -kInf, 0.05f, 9.0f, 1.0f};  // only the last is used
  const ScanView scan{0, 0.4, 0.1, 0.1, 2.0, ranges.data(), ranges.size()};
  ASSERT_EQ(mapper.addScan({0, 0, 0}, scan), "");
  int observed = 0;
  for (int j = 0; j < mapper.height(); ++j) {
    for (int i = 0; i < mapper.width(); ++i) {
      EXPECT_TRUE(std::isfinite(mapper.logOdds(i, j)));
      observed += mapper.observed(i, j);
    }
  }
  // One ray of 1 m at 0.4 rad from the centre of the map (cell coordinates 100, 100).
  EXPECT_EQ(observed,
            static_cast<int>(
                bruteCells(100, 100, 100 + 20 * std::cos(0.4), 100 + 20 * std::sin(0.4)).size()));
}

TEST(OccupancyMapper, ScansThatDoNotAddUpAreRefusedNamingTheFieldAndChangeNothing) {
  OccupancyMapper mapper(MapperOptions{});
  const std::vector<float> ranges(360, 1.0f);
  ScanView good{0, 359 * M_PI / 180, M_PI / 180, 0.12, 3.5, ranges.data(), ranges.size()};
  const auto refused = [&](ScanView scan, const std::string& field) {
    const std::string why = mapper.addScan({0, 0, 0}, scan);
    EXPECT_EQ(why.rfind(field + ":", 0), 0u) << why;
  };
  ScanView s = good;
  s.angle_max = 2 * M_PI;  // an increment of 360° / 360 but angle_max one ray further
  refused(s, "angle_max");
  s = good;
  s.angle_increment = std::nan("");
  refused(s, "angle_increment");
  s = good;
  s.range_max = 0.1;
  refused(s, "range_max");
  s = good;
  s.count = 0;
  refused(s, "ranges");
  s = good;
  s.angle_increment = 2 * M_PI / 180;
  s.angle_max = 359 * 2 * M_PI / 180;
  refused(s, "angle_increment");  // two turns
  EXPECT_EQ(mapper.addScan({std::nan(""), 0, 0}, good), "pose: not finite");
  EXPECT_EQ(mapper.scans(), 0u);
  for (std::int8_t v : mapper.grid().cells) ASSERT_EQ(v, OccupancyGrid::kUnknown);
  EXPECT_EQ(mapper.addScan({0, 0, 0}, good), "");
}

TEST(OccupancyMapper, HeadingAndAngleMinNearTheLargestDoubleAreTakenModuloATurn) {
  // Both finite, but their sum overflows to −inf (scan_fuzzer found it): the rays go where the
  // two angles within a turn point, as for any other heading.
  const double heading = -std::numeric_limits<double>::max(), angle_min = -9.16471e306;
  const std::vector<float> ranges = {1.2f, 0.8f, 1.5f};
  const auto map = [&](double theta, double first) {
    OccupancyMapper mapper(MapperOptions{});
    const ScanView scan{first, first + 0.2, 0.1, 0.1, 3.5, ranges.data(), ranges.size()};
    EXPECT_EQ(mapper.addScan({0.3, -0.2, theta}, scan), "");
    return mapper.grid().cells;
  };
  const std::vector<std::int8_t> reduced =
      map(std::remainder(heading, 2 * M_PI), std::remainder(angle_min, 2 * M_PI));
  EXPECT_EQ(std::count(reduced.begin(), reduced.end(), OccupancyGrid::kOccupied), 3);
  EXPECT_EQ(map(heading, angle_min), reduced);
}

TEST(OccupancyMapper, HostileScansNeverCrashNorLeaveAnythingButTrinaryCells) {
  // Extreme but finite fields, rays of every kind, poses far away: each scan is used or refused,
  // and the map stays a map.
  std::mt19937 rng(11);
  const double angles[] = {0, -1e300, 1e300, 3.14159, 1e-300, -7};
  const double increments[] = {0, 1e-300, 0.0174533, -0.01, 1e-7};
  const float ranges[] = {
      0.0f,  1e-40f, 1.0f, 3.4e38f, kInf, -kInf, std::numeric_limits<float>::quiet_NaN(),
      -1.0f, 50.0f};
  const double limits[] = {0, 1e-30, 3.5, 1e30, 3.4e38};
  const double coordinates[] = {0, 1e4, -1e5, 1e15, -1e300, 0.025};
  MapperOptions o;
  o.max_cells = 4'000'000;
  OccupancyMapper mapper(o);
  const auto pick = [&rng](const auto& values) {
    return values[std::uniform_int_distribution<std::size_t>(0, std::size(values) - 1)(rng)];
  };
  int used = 0;
  for (int n = 0; n < 3000; ++n) {
    std::vector<float> r(1 + rng() % 50);
    for (float& v : r) v = pick(ranges);
    ScanView scan{pick(angles), 0,        pick(increments), pick(limits),
                  pick(limits), r.data(), r.size()};
    scan.angle_max =
        rng() % 2 ? scan.angle_min + (r.size() - 1) * scan.angle_increment : pick(angles);
    used += mapper.addScan({pick(coordinates), pick(coordinates), pick(angles)}, scan).empty();
    mapper.addBump({pick(coordinates), pick(coordinates), pick(angles)}, 0.17, {true, true, false});
  }
  EXPECT_GT(used, 50);
  EXPECT_LE(static_cast<long long>(mapper.width()) * mapper.height(), o.max_cells);
  for (std::int8_t v : mapper.grid().cells) {
    ASSERT_TRUE(v == OccupancyGrid::kUnknown || v == OccupancyGrid::kFree ||
                v == OccupancyGrid::kOccupied);
  }
}

TEST(OccupancyMapper, TheCellsTheBumperPressedBecomeOccupied) {
  const world::World world = world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");
  OccupancyMapper mapper(optionsFor(world));
  const double r = 0.17;
  // Against the right wall (x = 6.4) head-on, then the top wall (y = 4.8) on the left switch.
  mapper.addBump({6.4 - r, 2.0, 0}, r, {true, true, true});
  mapper.addBump({3.0, 4.8 - r * std::sin(M_PI / 4) - 0.01, M_PI / 4 - 0.2}, r,
                 {true, true, false});
  mapper.addBump({3.0, 2.0, 0}, r, {});  // not pressed: nothing
  const OccupancyGrid map = mapper.grid();
  const MapAccuracy a = compare(map, world);
  EXPECT_EQ(a.occupied, 2u);
  EXPECT_EQ(a.known, 2u);
  EXPECT_EQ(a.walls_off, 0u);
  EXPECT_EQ(map.at(map.column(6.4 + 0.01), map.row(2.0)), OccupancyGrid::kOccupied);
}

TEST(OccupancyMapper, MapGrowsOnItsLatticeAndKeepsWhatItHad) {
  MapperOptions o;
  o.xmin = o.ymin = -1;
  o.xmax = o.ymax = 1;
  OccupancyMapper mapper(o);
  const float one = 0.5f;
  ASSERT_EQ(mapper.addScan({0, 0, 0}, {0, 0, 0, 0, 10, &one, 1}), "");
  const OccupancyGrid before = mapper.grid();
  const float far = 4.0f;
  ASSERT_EQ(mapper.addScan({0, 0.5, M_PI}, {0, 0, 0, 0, 10, &far, 1}), "");
  const OccupancyGrid after = mapper.grid();
  EXPECT_LE(after.origin.x, -4.0);
  EXPECT_EQ(after.at(after.column(-4.01), after.row(0.5)), OccupancyGrid::kOccupied);
  EXPECT_EQ(after.at(after.column(-3.99), after.row(0.5)), OccupancyGrid::kFree);
  // The first ray's hit (at x = 0.5) is where it was, on the same lattice.
  EXPECT_EQ(after.at(after.column(0.52), after.row(0.02)), OccupancyGrid::kOccupied);
  const double shift = (before.origin.x - after.origin.x) / o.resolution;
  EXPECT_NEAR(shift, std::round(shift), 1e-9);
}

TEST(OccupancyMapper, OptionsOutOfRangeAreRefusedNamingTheField) {
  const auto field = [](MapperOptions o) {
    try {
      OccupancyMapper mapper(o);
    } catch (const util::InvalidInput& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  MapperOptions o;
  o.resolution = 0;
  EXPECT_EQ(field(o), "resolution");
  o = {};
  o.xmax = o.xmin;
  EXPECT_EQ(field(o), "xmax");
  o = {};
  o.log_odds_free = 0.1;
  EXPECT_EQ(field(o), "log_odds_free");
  o = {};
  o.occupied_threshold = 1;
  EXPECT_EQ(field(o), "occupied_threshold");
  o = {};
  o.resolution = 0.001;
  o.xmin = o.ymin = -1000;
  o.xmax = o.ymax = 1000;
  EXPECT_EQ(field(o), "xmin, ymin, xmax, ymax");
  EXPECT_EQ(field(MapperOptions{}), "accepted");
}

}  // namespace
}  // namespace roomba_rrt::mapping
