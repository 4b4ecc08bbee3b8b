// The lab's scenarios, read from config/rrt_scenarios.yaml. (The simulator's room as a problem:
// world_planning/room_problem.h.)
#pragma once

#include <map>
#include <string>

#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::planning {

/// Reads a scenario file (see config/rrt_scenarios.yaml for the format). Throws
/// util::InvalidInput naming the file and the field on a malformed file.
std::map<std::string, Problem> loadScenarios(const std::string& path);

}  // namespace roomba_rrt::planning
