#include "roomba_rrt/geometry/map_file.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

#include "roomba_rrt/geometry/map_image.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"
#include "roomba_rrt/util/text_file.h"
#include "roomba_rrt/util/yaml_reader.h"

namespace roomba_rrt::geometry {
namespace {

using util::InvalidInput;

/// The keys a map_server YAML may have (Nav2's `mode` included).
const std::set<std::string> kKeys = {"image",           "resolution",  "origin", "negate",
                                     "occupied_thresh", "free_thresh", "mode"};

double number(const YAML::Node& root, const char* key) {
  const YAML::Node node = root[key];
  if (!node.IsScalar()) throw InvalidInput(key, "must be a number");
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw InvalidInput(key, "must be a number, got '" + node.Scalar() + "'");
  }
}

/// The grid of the decoded image, map_server's way. A pixel's cell depends only on the sum of its
/// channels, so each possible sum is read once (trinaryValue) and the pixels look theirs up.
void readPixels(const MapImage& image, const MapFile& map, OccupancyGrid& grid) {
  const int channels = image.channels;
  std::vector<std::int8_t> cell_of_sum(static_cast<std::size_t>(255 * channels + 1));
  for (std::size_t sum = 0; sum < cell_of_sum.size(); ++sum) {
    cell_of_sum[sum] = trinaryValue(static_cast<double>(sum) / channels, map.negate,
                                    map.occupied_thresh, map.free_thresh);
  }
  grid.width = image.width;
  grid.height = image.height;
  grid.cells.resize(static_cast<std::size_t>(image.width) * image.height);
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * channels;
  for (int j = 0; j < image.height; ++j) {
    const unsigned char* row = image.pixels.data() + static_cast<std::size_t>(j) * row_bytes;
    // Image row 0 is the top: the grid's last row.
    std::int8_t* out =
        grid.cells.data() + static_cast<std::size_t>(image.height - 1 - j) * image.width;
    if (channels == 1) {
      for (int i = 0; i < image.width; ++i) out[i] = cell_of_sum[row[i]];
      continue;
    }
    for (int i = 0; i < image.width; ++i) {
      const unsigned char* p = row + static_cast<std::size_t>(i) * channels;
      int sum = 0;
      for (int k = 0; k < channels; ++k) sum += p[k];
      out[i] = cell_of_sum[static_cast<std::size_t>(sum)];
    }
  }
}

void readImage(MapFile& map, long long max_cells) {
  std::error_code error;
  const auto status = std::filesystem::status(map.image, error);
  if (error || !std::filesystem::exists(status)) {
    throw InvalidInput("image", "'" + map.image + "' does not exist");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InvalidInput("image", "'" + map.image + "' is not a regular file");
  }
  const auto bytes = std::filesystem::file_size(map.image, error);
  if (error || bytes > MapLimits::kMaxImageBytes) {
    throw InvalidInput("image", "'" + map.image + "' has more than " +
                                    std::to_string(MapLimits::kMaxImageBytes) + " bytes");
  }
  const MapImage image = decodeMapImage(map.image, max_cells);  // size checked first
  readPixels(image, map, map.grid);
}

void readYaml(const std::string& text, MapFile& map) {
  const YAML::Node root = util::parseYaml(text);
  if (!root.IsMap())
    throw InvalidInput("", "must be a mapping (image:, resolution:, origin:, ...)");
  for (const auto& pair : root) {
    const std::string key = pair.first.Scalar();
    if (!kKeys.count(key)) throw InvalidInput(key, "is not a map_server key");
  }
  for (const char* key : {"image", "resolution", "origin"}) {
    if (!root[key]) throw InvalidInput(key, "is missing");
  }
  if (!root["image"].IsScalar() || root["image"].Scalar().empty()) {
    throw InvalidInput("image", "must be a file name");
  }
  const std::filesystem::path image = root["image"].Scalar();
  map.image = image.is_absolute()
                  ? image.string()
                  : (std::filesystem::path(map.yaml).parent_path() / image).string();

  map.resolution = number(root, "resolution");
  const YAML::Node origin = root["origin"];
  if (!origin.IsSequence() || (origin.size() != 2 && origin.size() != 3)) {
    throw InvalidInput("origin", "must be [x, y, yaw]");
  }
  double values[3] = {0, 0, 0};
  for (std::size_t k = 0; k < origin.size(); ++k) {
    const std::string field = util::entry("origin", k);
    try {
      values[k] = origin[k].as<double>();
    } catch (const YAML::Exception&) {
      throw InvalidInput(field, "must be a number");
    }
  }
  validateMapPlacement(map.resolution, values[0], values[1], values[2]);
  map.origin = {values[0], values[1]};

  if (root["negate"]) {
    const double negate = number(root, "negate");
    util::require(negate == 0 || negate == 1, "negate", "0 or 1", negate);
    map.negate = negate == 1;
  }
  if (root["occupied_thresh"]) map.occupied_thresh = number(root, "occupied_thresh");
  if (root["free_thresh"]) map.free_thresh = number(root, "free_thresh");
  util::requireInRange("occupied_thresh", map.occupied_thresh, 0, 1);
  util::requireInRange("free_thresh", map.free_thresh, 0, 1);
  if (!(map.free_thresh < map.occupied_thresh)) {
    throw InvalidInput("free_thresh", "must be below occupied_thresh (" +
                                          util::show(map.occupied_thresh) + "), got " +
                                          util::show(map.free_thresh));
  }
  if (root["mode"] && root["mode"].Scalar() != "trinary") {
    throw InvalidInput("mode", "only 'trinary' is read (free, occupied, unknown), got '" +
                                   root["mode"].Scalar() + "'");
  }
  // map_server refuses a file without these (its defaults are not the user's choice).
  for (const char* key : {"negate", "occupied_thresh", "free_thresh"}) {
    if (!root[key]) throw InvalidInput(key, "is missing; map_server requires it");
  }
}

}  // namespace

void validateMapPlacement(double resolution, double x, double y, double rotation,
                          const MapFieldNames& names) {
  util::requireInRange(names.resolution, resolution, MapLimits::kMinResolution,
                       MapLimits::kMaxResolution, "m");
  util::requireInRange(names.x, x, -MapLimits::kMaxCoordinate, MapLimits::kMaxCoordinate, "m");
  util::requireInRange(names.y, y, -MapLimits::kMaxCoordinate, MapLimits::kMaxCoordinate, "m");
  if (!(std::abs(rotation) <= 1e-6)) {
    throw InvalidInput(names.rotation, "a rotated map (by " + util::show(rotation) +
                                           " rad) is not supported; rotate the image and use "
                                           "yaw 0");
  }
}

std::int8_t trinaryValue(double average, bool negate, double occupied_thresh, double free_thresh) {
  if (negate) average = 255.0 - average;
  const double occupancy = (255.0 - average) / 255.0;
  if (occupancy > occupied_thresh) return OccupancyGrid::kOccupied;
  if (occupancy < free_thresh) return OccupancyGrid::kFree;
  return OccupancyGrid::kUnknown;
}

MapFile loadMap(const std::string& yaml_path, long long max_cells) {
  MapFile map;
  map.yaml = yaml_path;
  try {
    readYaml(util::readTextFile(yaml_path, MapLimits::kMaxYamlBytes, "map file"), map);
    readImage(map, max_cells);
  } catch (const InvalidInput& e) {
    throw e.source().empty() ? e.in(yaml_path) : e;
  } catch (const YAML::Exception& e) {
    throw InvalidInput("", std::string("malformed map file: ") + e.what(), yaml_path);
  }
  map.grid.resolution = map.resolution;
  map.grid.origin = map.origin;
  return map;
}

bool isMapYaml(const std::string& path) {
  // Whether the first document's top level is a mapping with an `image` key, read from yaml-cpp's
  // events: no node graph is built, so an alias (refused by loadMap, naming its line) is never
  // followed. Leniently: a map with a mistake (a key twice, an alias) is still a map.
  class ImageKey : public YAML::EventHandler {
   public:
    bool found = false;
    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override { node(""); }
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override { node(""); }
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  const std::string& value) override {
      node(value);
    }
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {
      ++depth_;
    }
    void OnSequenceEnd() override { end(); }
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {
      if (depth_ == 0) top_is_map_ = true;
      ++depth_;
    }
    void OnMapEnd() override { end(); }

   private:
    void node(const std::string& scalar) {  // a whole node ends at depth_
      if (depth_ != 1 || !top_is_map_) return;
      if (nodes_++ % 2 == 0 && scalar == "image") found = true;  // a key, not a value
    }
    void end() {
      --depth_;
      node("");
    }
    int depth_ = 0;
    long nodes_ = 0;
    bool top_is_map_ = false;
  };
  try {
    std::istringstream in(util::readTextFile(path, MapLimits::kMaxYamlBytes, "map file"));
    YAML::Parser parser(in);
    ImageKey image;
    parser.HandleNextDocument(image);
    return image.found;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace roomba_rrt::geometry
