#include "roomba_rrt/planning/lab/scenarios.h"

#include <initializer_list>

#include <yaml-cpp/yaml.h>

#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/text_file.h"
#include "roomba_rrt/util/yaml_reader.h"

namespace roomba_rrt::planning {
namespace {

constexpr std::size_t kMaxScenarioFileBytes = 1 << 20;  // a scenario file is at most 1 MiB

[[noreturn]] void fail(const std::string& file, const std::string& field, const std::string& why) {
  throw util::InvalidInput(field, why, file);
}

Point2 readPoint(const YAML::Node& node, const std::string& file, const std::string& field) {
  if (!node || !node.IsSequence() || node.size() != 2) fail(file, field, "expected [x, y]");
  return {node[0].as<double>(), node[1].as<double>()};
}

// Reads the required numbers `keys` of the map `node` (the field's name is node's).
void readNumbers(const YAML::Node& node, const std::string& file, const std::string& field,
                 std::initializer_list<std::pair<const char*, double*>> keys) {
  for (const auto& [key, value] : keys) {
    if (!node[key]) fail(file, field + "." + key, "missing");
    *value = node[key].as<double>();
  }
}

Bounds readBounds(const YAML::Node& node, const std::string& file, const std::string& field) {
  Bounds b;
  readNumbers(node, file, field,
              {{"x_min", &b.x_min}, {"x_max", &b.x_max}, {"y_min", &b.y_min}, {"y_max", &b.y_max}});
  return b;
}

}  // namespace

std::map<std::string, Problem> loadScenarios(const std::string& path) {
  YAML::Node root;
  try {
    root = util::parseYaml(util::readTextFile(path, kMaxScenarioFileBytes, "scenario file"));
  } catch (const util::InvalidInput& e) {
    throw e.source().empty() ? e.in(path) : e;
  }
  std::map<std::string, Problem> scenarios;
  try {
    const Bounds defaults = root["bounds"] ? readBounds(root["bounds"], path, "bounds") : Bounds{};
    if (!root["scenarios"] || !root["scenarios"].IsMap()) fail(path, "scenarios", "missing map");
    for (const auto& entry : root["scenarios"]) {
      const std::string name = entry.first.as<std::string>();
      const YAML::Node& s = entry.second;
      const std::string field = "scenarios." + name;
      Problem p;
      p.start = readPoint(s["start"], path, field + ".start");
      p.goal = readPoint(s["goal"], path, field + ".goal");
      p.bounds = s["bounds"] ? readBounds(s["bounds"], path, field + ".bounds") : defaults;
      int i = 0;
      for (const auto& o : s["obstacles"]) {
        const std::string obstacle = util::entry(field + ".obstacles", i++);
        if (!o["radius"]) fail(path, obstacle + ".radius", "missing");
        p.obstacles.push_back(
            {readPoint(o["center"], path, obstacle + ".center"), o["radius"].as<double>()});
      }
      i = 0;
      for (const auto& r : s["rectangles"]) {
        const std::string rectangle = util::entry(field + ".rectangles", i++);
        Rectangle box;
        readNumbers(r, path, rectangle,
                    {{"min_x", &box.min_x},
                     {"min_y", &box.min_y},
                     {"max_x", &box.max_x},
                     {"max_y", &box.max_y}});
        p.rectangles.push_back(box);
      }
      if (s["robot_radius"]) p.robot_radius = s["robot_radius"].as<double>();
      if (s["clearance"]) p.clearance = s["clearance"].as<double>();
      scenarios.emplace(name, std::move(p));
    }
  } catch (const YAML::Exception& e) {
    throw util::InvalidInput("", std::string("malformed scenarios: ") + e.what(), path);
  }
  return scenarios;
}

}  // namespace roomba_rrt::planning
