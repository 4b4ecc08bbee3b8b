// Map files read as map_server reads them: tiny hand-made PGM (P5, P2) and PNG images (written
// with libpng) with every threshold edge, negate, row order and origin; every bad map refused
// naming the file and the field; the real maps of ../shared/maps read with their sizes.
#include "roomba_rrt/geometry/map_file.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../common/hostile_yaml.h"
#include "../common/shared_maps.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::geometry {
namespace {

namespace fs = std::filesystem;

class MapFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(testing::TempDir()) /
           ("map_file_test_" +
            std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  /// A binary PGM (P5) of `width` x `height` grey values, top row first.
  std::string pgm(const std::string& name, int width, int height,
                  const std::vector<unsigned char>& grey) {
    return write(name, "P5\n# a comment\n" + std::to_string(width) + " " + std::to_string(height) +
                           "\n255\n" + std::string(grey.begin(), grey.end()));
  }
  /// A PNG with `channels` bytes per pixel (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA), top row first.
  std::string png(const std::string& name, int width, int height, int channels,
                  const std::vector<unsigned char>& bytes) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = width;
    image.height = height;
    image.format = channels == 1   ? PNG_FORMAT_GRAY
                   : channels == 2 ? PNG_FORMAT_GA
                   : channels == 3 ? PNG_FORMAT_RGB
                                   : PNG_FORMAT_RGBA;
    const std::string path = (dir_ / name).string();
    EXPECT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, bytes.data(), 0, nullptr));
    return path;
  }
  std::string yaml(const std::string& image, const std::string& extra = "") {
    return write("map.yaml", "image: " + image + "\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\n" +
                                 "negate: 0\noccupied_thresh: 0.6\nfree_thresh: 0.2\n" + extra);
  }
  std::string errorOf(const std::string& yaml_path) {
    try {
      loadMap(yaml_path);
    } catch (const util::InvalidInput& e) {
      return e.what();
    }
    return "accepted";
  }

  fs::path dir_;
};

TEST_F(MapFileTest, the_thresholds_are_strict_as_in_map_server) {
  // occupancy = (255 - p) / 255: p 102 is exactly 0.6, p 204 exactly 0.2.
  EXPECT_EQ(trinaryValue(101, false, 0.6, 0.2), OccupancyGrid::kOccupied);
  EXPECT_EQ(trinaryValue(102, false, 0.6, 0.2), OccupancyGrid::kUnknown);  // not above
  EXPECT_EQ(trinaryValue(204, false, 0.6, 0.2), OccupancyGrid::kUnknown);  // not below
  EXPECT_EQ(trinaryValue(205, false, 0.6, 0.2), OccupancyGrid::kFree);
  EXPECT_EQ(trinaryValue(0, false, 0.6, 0.2), OccupancyGrid::kOccupied);
  EXPECT_EQ(trinaryValue(255, false, 0.6, 0.2), OccupancyGrid::kFree);
  // negate: occupancy = p / 255.
  EXPECT_EQ(trinaryValue(255, true, 0.6, 0.2), OccupancyGrid::kOccupied);
  EXPECT_EQ(trinaryValue(0, true, 0.6, 0.2), OccupancyGrid::kFree);
  EXPECT_EQ(trinaryValue(153, true, 0.6, 0.2), OccupancyGrid::kUnknown);
}

TEST_F(MapFileTest, a_pgm_is_read_bottom_row_first_with_its_resolution_and_origin) {
  // Top row: black, threshold, white; bottom row: 205, 204, 101.
  pgm("m.pgm", 3, 2, {0, 102, 255, 205, 204, 101});
  const MapFile map = loadMap(yaml("m.pgm"));
  const OccupancyGrid& g = map.grid;
  ASSERT_EQ(g.width, 3);
  ASSERT_EQ(g.height, 2);
  EXPECT_DOUBLE_EQ(g.resolution, 0.5);
  EXPECT_DOUBLE_EQ(g.origin.x, -1.0);
  EXPECT_DOUBLE_EQ(g.origin.y, 2.0);
  EXPECT_EQ(g.at(0, 1), OccupancyGrid::kOccupied);  // the image's top-left
  EXPECT_EQ(g.at(1, 1), OccupancyGrid::kUnknown);
  EXPECT_EQ(g.at(2, 1), OccupancyGrid::kFree);
  EXPECT_EQ(g.at(0, 0), OccupancyGrid::kFree);
  EXPECT_EQ(g.at(1, 0), OccupancyGrid::kUnknown);
  EXPECT_EQ(g.at(2, 0), OccupancyGrid::kOccupied);
  EXPECT_EQ(map.image, (dir_ / "m.pgm").string());  // relative to the YAML
}

TEST_F(MapFileTest, negate_swaps_black_and_white) {
  pgm("m.pgm", 2, 1, {0, 255});
  const OccupancyGrid g = loadMap(yaml("m.pgm")).grid;
  EXPECT_EQ(g.at(0, 0), OccupancyGrid::kOccupied);
  write("neg.yaml",
        "image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\nnegate: 1\noccupied_thresh: 0.6\n"
        "free_thresh: 0.2\n");
  const OccupancyGrid n = loadMap((dir_ / "neg.yaml").string()).grid;
  EXPECT_EQ(n.at(0, 0), OccupancyGrid::kFree);
  EXPECT_EQ(n.at(1, 0), OccupancyGrid::kOccupied);
}

TEST_F(MapFileTest, an_ascii_pgm_reads_like_the_binary_one) {
  write("a.pgm", "P2\n# ascii\n3 2\n255\n0 102 255\n205 204 101\n");
  pgm("b.pgm", 3, 2, {0, 102, 255, 205, 204, 101});
  EXPECT_EQ(loadMap(yaml("a.pgm")).grid.cells, loadMap(yaml("b.pgm")).grid.cells);
}

TEST_F(MapFileTest, png_channels_are_averaged_as_map_server_averages_them) {
  pgm("ref.pgm", 4, 1, {0, 102, 204, 255});
  const std::vector<std::int8_t> expected = loadMap(yaml("ref.pgm")).grid.cells;
  png("g.png", 4, 1, 1, {0, 102, 204, 255});
  EXPECT_EQ(loadMap(yaml("g.png")).grid.cells, expected);
  png("rgb.png", 4, 1, 3, {0, 0, 0, 100, 102, 104, 204, 204, 204, 255, 255, 255});
  EXPECT_EQ(loadMap(yaml("rgb.png")).grid.cells, expected);
  // Trinary mode averages every byte, alpha included: (3 * 255 + 0) / 4 = 191.25 is unknown
  // (occupancy 0.25), (3 * 255 + 255) / 4 = 255 free.
  png("rgba.png", 2, 1, 4, {255, 255, 255, 0, 255, 255, 255, 255});
  const std::vector<std::int8_t> rgba = loadMap(yaml("rgba.png")).grid.cells;
  EXPECT_EQ(rgba, (std::vector<std::int8_t>{OccupancyGrid::kUnknown, OccupancyGrid::kFree}));
  png("ga.png", 2, 1, 2, {255, 0, 255, 255});
  EXPECT_EQ(loadMap(yaml("ga.png")).grid.cells, rgba);
}

TEST_F(MapFileTest, every_bad_map_is_refused_naming_the_file_and_the_field) {
  pgm("m.pgm", 2, 2, {0, 0, 255, 255});
  const std::string file = (dir_ / "map.yaml").string();
  const auto refused = [&](const std::string& text, const std::string& expected) {
    write("map.yaml", text);
    const std::string error = errorOf(file);
    EXPECT_EQ(error.rfind(file + ": " + expected, 0), 0u) << error;
  };
  const std::string place = "resolution: 0.5\norigin: [0, 0, 0]\n";
  const std::string ok = place + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  refused("image: none.pgm\n" + ok, "image: '" + (dir_ / "none.pgm").string() + "' does not exist");
  refused("image: m.pgm\nresolution: 0\norigin: [0, 0, 0]\n",
          "resolution: must be in [0.0001, 100] m, got 0");
  refused("image: m.pgm\nresolution: -1\norigin: [0, 0, 0]\n", "resolution: must be in");
  refused("image: m.pgm\nresolution: abc\norigin: [0, 0, 0]\n", "resolution: must be a number");
  refused("image: m.pgm\n" + place + "occupied_thresh: 1.5\n",
          "occupied_thresh: must be in [0, 1]");
  refused("image: m.pgm\n" + place + "free_thresh: -0.1\n", "free_thresh: must be in [0, 1]");
  refused("image: m.pgm\n" + place + "occupied_thresh: 0.3\nfree_thresh: 0.3\n",
          "free_thresh: must be below occupied_thresh (0.3), got 0.3");
  refused("image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0.5]\n", "origin[2]: a rotated map");
  refused("image: m.pgm\nresolution: 0.5\norigin: [0, .nan, 0]\n", "origin[1]: must be in");
  refused("image: m.pgm\n" + place + "negate: 2\n", "negate: must be 0 or 1, got 2");
  // Issue 44, item 3: what map_server requires, and where it lies, as for a message on /map.
  refused("image: m.pgm\n" + place + "negate: 0\noccupied_thresh: 0.65\n",
          "free_thresh: is missing; map_server requires it");
  refused("image: m.pgm\n" + place + "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
          "negate: is missing; map_server requires it");
  refused("image: m.pgm\n" + place + "negate: 0\nfree_thresh: 0.196\n",
          "occupied_thresh: is missing; map_server requires it");
  refused("image: m.pgm\n" + place + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: ~\n",
          "free_thresh: must be a number");
  refused("image: m.pgm\nresolution: 1e-30\norigin: [0, 0, 0]\n",
          "resolution: must be in [0.0001, 100] m, got 1e-30");
  refused("image: m.pgm\nresolution: 0.5\norigin: [0, 2e6, 0]\n",
          "origin[1]: must be in [-1e+06, 1e+06] m, got 2e+06");
  refused("image: m.pgm\n" + ok + "mode: scale\n", "mode: only 'trinary' is read");
  refused("image: m.pgm\n" + ok + "resolutoin: 0.1\n", "resolutoin: is not a map_server key");
  refused("image: m.pgm\n" + ok + "image: n.pgm\n", "image: is given twice (lines 1 and 7)");
  refused("resolution: 0.5\norigin: [0, 0, 0]\n", "image: is missing");
  // Issue 44: a valid map plus an alias bomb kept the tools busy for 70 minutes.
  refused("image: m.pgm\n" + ok + roomba_rrt::test::aliasBomb(9),
          roomba_rrt::test::aliasRefusal(7, 5));
  refused("image: m.pgm\nresolution: &r 0.5\norigin: [0, 0, 0]\n",
          roomba_rrt::test::aliasRefusal(2, 13));
  refused(roomba_rrt::test::kRecursiveAlias, roomba_rrt::test::aliasRefusal(1, 7));
  refused("image: m.pgm\nresolution: 0.5\n", "origin: is missing");
  // Images: truncated, not an image, a header claiming too many pixels (refused before decoding).
  write("short.pgm", "P5\n4 4\n255\nabc");
  refused("image: short.pgm\n" + ok, "image: cannot decode");
  write("text.pgm", "hello, not an image");
  refused("image: text.pgm\n" + ok,
          "image: '" + (dir_ / "text.pgm").string() + "' is not a PGM or PNG image");
  write("huge.pgm", "P5\n200000 200000\n255\n");
  refused("image: huge.pgm\n" + ok, "image: '" + (dir_ / "huge.pgm").string() +
                                        "' has 200000 x 200000 pixels; at most 100000000");
  write("empty.pgm", "P5\n0 3\n255\n");
  refused("image: empty.pgm\n" + ok,
          "image: '" + (dir_ / "empty.pgm").string() + "' has no pixels");
  refused("image: .\n" + ok, "image: '" + (dir_ / ".").string() + "' is not a regular file");
  EXPECT_EQ(errorOf((dir_ / "nothing.yaml").string()).rfind((dir_ / "nothing.yaml").string(), 0),
            0u);
}

TEST_F(MapFileTest, is_map_yaml_tells_a_map_from_a_world_file) {
  pgm("m.pgm", 1, 1, {255});
  EXPECT_TRUE(isMapYaml(yaml("m.pgm")));
  EXPECT_FALSE(isMapYaml(write("world.yaml", "room: {width: 3, height: 3}\n")));
  EXPECT_FALSE(isMapYaml((dir_ / "missing.yaml").string()));
  EXPECT_FALSE(isMapYaml(write("nested.yaml", "room: {image: m.pgm}\nlist: [image]\n")));
  EXPECT_FALSE(isMapYaml(write("value.yaml", "name: image\n")));
  EXPECT_FALSE(isMapYaml(write("list.yaml", "[image, 1]\n")));
  EXPECT_TRUE(isMapYaml(write("late.yaml", "a: {b: [1, {c: 2}]}\nimage: m.pgm\n")));
  // A map with an alias bomb is a map (which loadMap then refuses, naming the line), told at once.
  EXPECT_TRUE(isMapYaml(write("bomb.yaml", "image: m.pgm\n" + roomba_rrt::test::aliasBomb(9))));
  EXPECT_FALSE(isMapYaml(write("recursive.yaml", roomba_rrt::test::kRecursiveAlias)));
}

/// The real maps of ../shared/maps (not part of the package: skipped when absent, see
/// test/common/shared_maps.h).
TEST(SharedMaps, every_map_reads_with_its_published_size_and_has_free_floor) {
  const struct {
    const char* name;
    int width, height;
    double resolution;
  } kMaps[] = {{"turtlebot3_world", 384, 384, 0.05},
               {"depot", 604, 307, 0.05},
               {"warehouse", 1006, 1674, 0.03},
               {"nav2_bench_100by100_15", 2000, 2000, 0.05},
               {"willow_full", 540, 587, 0.1}};
  for (const auto& m : kMaps) {
    ROOMBA_RRT_REQUIRE_SHARED_MAP(m.name);
    const MapFile map = loadMap(::roomba_rrt::test::sharedMapPath(m.name));
    EXPECT_EQ(map.grid.width, m.width) << m.name;
    EXPECT_EQ(map.grid.height, m.height) << m.name;
    EXPECT_DOUBLE_EQ(map.grid.resolution, m.resolution) << m.name;
    std::size_t free = 0, occupied = 0;
    for (const std::int8_t c : map.grid.cells) {
      free += c == OccupancyGrid::kFree;
      occupied += c == OccupancyGrid::kOccupied;
    }
    EXPECT_GT(free, map.grid.cells.size() / 20) << m.name;
    EXPECT_GT(occupied, 0u) << m.name;
  }
}

}  // namespace
}  // namespace roomba_rrt::geometry
