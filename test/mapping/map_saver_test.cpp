// Saving a map as map_saver does (map_saver.h) and reading it back as map_server does
// (geometry/map_file.h): the same cells, resolution and origin.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/mapping/map_saver.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::mapping {
namespace {

using geometry::OccupancyGrid;

std::string temporaryFolder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   (name + "_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(MapSaver, PixelsAreMapSaversThresholds) {
  EXPECT_EQ(pgmValue(0), 254);
  EXPECT_EQ(pgmValue(25), 254);
  EXPECT_EQ(pgmValue(26), 205);
  EXPECT_EQ(pgmValue(64), 205);
  EXPECT_EQ(pgmValue(65), 0);
  EXPECT_EQ(pgmValue(100), 0);
  EXPECT_EQ(pgmValue(-1), 205);
}

TEST(MapSaver, SavedMapReadsBackAsTheSameGrid) {
  OccupancyGrid grid;
  grid.width = 7;
  grid.height = 5;
  grid.resolution = 0.05;
  grid.origin = {-1.35, 2.1};
  const std::int8_t values[] = {OccupancyGrid::kFree, OccupancyGrid::kOccupied,
                                OccupancyGrid::kUnknown};
  for (int k = 0; k < 35; ++k) grid.cells.push_back(values[(k * k + k / 3) % 3]);
  const std::string dir = temporaryFolder("map_saver_test");
  const std::string yaml = saveMap(grid, dir + "/built");
  EXPECT_EQ(yaml, dir + "/built.yaml");
  const geometry::MapFile map = geometry::loadMap(yaml);
  EXPECT_EQ(map.image, dir + "/built.pgm");
  EXPECT_EQ(map.grid.width, grid.width);
  EXPECT_EQ(map.grid.height, grid.height);
  EXPECT_EQ(map.grid.resolution, grid.resolution);
  EXPECT_EQ(map.grid.origin.x, grid.origin.x);
  EXPECT_EQ(map.grid.origin.y, grid.origin.y);
  EXPECT_EQ(map.grid.cells, grid.cells);
  // The YAML is map_saver's (the image named relative to it).
  std::ifstream in(yaml);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "image: built.pgm\nresolution: 0.05\norigin: [-1.35, 2.1, 0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  std::filesystem::remove_all(dir);
}

TEST(MapSaver, ResolutionOfAMessageIsWrittenAsTheShortestTextOfItsFloat) {
  OccupancyGrid grid;
  grid.width = grid.height = 1;
  grid.resolution = static_cast<float>(0.05);  // what nav_msgs/MapMetaData carries
  grid.origin = {-10, 0.1};
  grid.cells = {0};
  const std::string yaml = mapYaml(grid, "m.pgm");
  EXPECT_NE(yaml.find("resolution: 0.05\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("origin: [-10, 0.1, 0]\n"), std::string::npos) << yaml;
}

TEST(MapSaver, UnwritableFolderIsNamed) {
  OccupancyGrid grid;
  grid.width = grid.height = 1;
  grid.resolution = 1;
  grid.cells = {0};
  try {
    saveMap(grid, "/nonexistent_folder_for_map_saver/map");
    FAIL() << "saved";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(e.field(), "/nonexistent_folder_for_map_saver/map.pgm");
  }
  EXPECT_THROW(saveMap(OccupancyGrid{}, "/tmp/empty"), util::InvalidInput);
}

}  // namespace
}  // namespace roomba_rrt::mapping
