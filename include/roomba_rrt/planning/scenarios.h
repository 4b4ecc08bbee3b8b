// The lab's scenarios, read from config/rrt_scenarios.yaml.
#pragma once

#include <map>
#include <string>

#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {

/// Reads a scenario file (see config/rrt_scenarios.yaml for the format). Throws
/// std::runtime_error naming the file and the field on a malformed file.
std::map<std::string, Problem> loadScenarios(const std::string& path);

/// config/rrt_scenarios.yaml of the source tree this library was built from.
std::string defaultScenarioFile();

}  // namespace roomba_rrt::planning
