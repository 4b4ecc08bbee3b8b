#include "roomba_rrt/planning/scenarios.h"

#include <stdexcept>

#include <yaml-cpp/yaml.h>

namespace roomba_rrt::planning {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& field, const std::string& why) {
  throw std::runtime_error(file + ": " + field + ": " + why);
}

Point2 readPoint(const YAML::Node& node, const std::string& file, const std::string& field) {
  if (!node || !node.IsSequence() || node.size() != 2) fail(file, field, "expected [x, y]");
  return {node[0].as<double>(), node[1].as<double>()};
}

Bounds readBounds(const YAML::Node& node, const std::string& file, const std::string& field) {
  Bounds b;
  for (const auto& [key, value] : {std::pair<const char*, double*>{"x_min", &b.x_min},
                                   {"x_max", &b.x_max},
                                   {"y_min", &b.y_min},
                                   {"y_max", &b.y_max}}) {
    if (!node[key]) fail(file, field + "." + key, "missing");
    *value = node[key].as<double>();
  }
  return b;
}

}  // namespace

std::map<std::string, Problem> loadScenarios(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": cannot read scenarios: " + e.what());
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
        const std::string obstacle = field + ".obstacles[" + std::to_string(i++) + "]";
        if (!o["radius"]) fail(path, obstacle + ".radius", "missing");
        p.obstacles.push_back(
            {readPoint(o["center"], path, obstacle + ".center"), o["radius"].as<double>()});
      }
      scenarios.emplace(name, std::move(p));
    }
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": malformed scenarios: " + e.what());
  }
  return scenarios;
}

std::string defaultScenarioFile() { return RRT_SCENARIO_FILE; }

}  // namespace roomba_rrt::planning
