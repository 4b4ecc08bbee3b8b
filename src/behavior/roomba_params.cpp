#include "roomba_rrt/behavior/roomba_params.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <map>
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"
#include "roomba_rrt/util/text_file.h"
#include "roomba_rrt/util/yaml_reader.h"

namespace roomba_rrt::behavior {
namespace {

using util::InvalidInput;
using util::require;

}  // namespace

void validate(const RoombaParams& p) {
  using L = RoombaParamLimits;
  const std::pair<const char*, double> all[] = {{"move_forward_time", p.move_forward_time},
                                                {"move_in_spiral_time", p.move_in_spiral_time},
                                                {"go_back_time", p.go_back_time},
                                                {"forward_speed", p.forward_speed},
                                                {"backward_speed", p.backward_speed},
                                                {"angular_speed", p.angular_speed},
                                                {"initial_radius_spiral", p.initial_radius_spiral},
                                                {"spiral_factor", p.spiral_factor},
                                                {"rate", p.rate}};
  for (const auto& [field, value] : all) require(std::isfinite(value), field, "finite", value);
  for (const auto& [field, value] : {all[0], all[1], all[2]}) {
    require(value >= 0 && value <= L::kMaxTime, field, "in [0, 1e6] s", value);
  }
  require(p.forward_speed > 0 && p.forward_speed <= L::kMaxSpeed, "forward_speed", "in (0, 100]",
          p.forward_speed);
  require(p.backward_speed < 0 && p.backward_speed >= -L::kMaxSpeed, "backward_speed",
          "in [-100, 0) (it drives backwards)", p.backward_speed);
  require(p.angular_speed > 0 && p.angular_speed <= L::kMaxSpeed, "angular_speed", "in (0, 100]",
          p.angular_speed);
  require(p.initial_radius_spiral > 0 && p.initial_radius_spiral <= L::kMaxSpiral,
          "initial_radius_spiral", "in (0, 1000]", p.initial_radius_spiral);
  require(p.spiral_factor >= 0 && p.spiral_factor <= L::kMaxSpiral, "spiral_factor", "in [0, 1000]",
          p.spiral_factor);
  require(p.rate >= L::kMinRate && p.rate <= L::kMaxRate, "rate", "in [1, 1000] Hz", p.rate);
}

RoombaParams parseRoombaParams(const std::string& yaml_text, const std::string& source) {
  RoombaParams p;
  const std::map<std::string, double*> fields = {
      {"move_forward_time", &p.move_forward_time},
      {"move_in_spiral_time", &p.move_in_spiral_time},
      {"go_back_time", &p.go_back_time},
      {"forward_speed", &p.forward_speed},
      {"backward_speed", &p.backward_speed},
      {"angular_speed", &p.angular_speed},
      {"initial_radius_spiral", &p.initial_radius_spiral},
      {"spiral_factor", &p.spiral_factor},
      {"rate", &p.rate}};
  try {
    const YAML::Node root = util::parseYaml(yaml_text);
    if (root.IsNull()) return p;  // an empty file keeps every default
    if (!root.IsMap()) throw InvalidInput("", "the top level must be a map of parameters");
    for (const auto& entry : root) {
      const std::string key = entry.first.as<std::string>();
      const auto field = fields.find(key);
      if (field == fields.end()) throw InvalidInput(key, "is not a known parameter");
      try {
        *field->second = entry.second.as<double>();
      } catch (const YAML::Exception&) {
        throw InvalidInput(key, "must be a number");
      }
    }
    validate(p);
  } catch (const YAML::Exception& e) {
    throw InvalidInput("", e.what(), source);
  } catch (const InvalidInput& e) {
    throw e.in(source);
  }
  return p;
}

RoombaParams loadRoombaParams(const std::string& yaml_path) {
  return parseRoombaParams(util::readTextFile(yaml_path, 1 << 20, "parameter file"), yaml_path);
}

}  // namespace roomba_rrt::behavior
