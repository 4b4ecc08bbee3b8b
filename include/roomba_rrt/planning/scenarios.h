// The lab's scenarios, read from config/rrt_scenarios.yaml, and the simulator's room.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::planning {

/// Reads a scenario file (see config/rrt_scenarios.yaml for the format). Throws
/// util::InvalidInput naming the file and the field on a malformed file.
std::map<std::string, Problem> loadScenarios(const std::string& path);

/// The simulator's room as a planning problem (scenario `room`): bounds = the room's walls (a
/// map's extent), obstacles = its furniture (circles and rectangles) and its map's occupied and
/// unknown cells, robot_radius = the world's robot, start and goal = the robot's initial position
/// (callers set their own).
Problem roomProblem(const world::World& world);

/// A map as a planning problem (scenario `map`): bounds = its extent, obstacles = its occupied
/// cells, and its unknown cells unless `allow_unknown`. Start, goal and the robot are the
/// caller's. Costs the map's distance transform (about 10 ns per cell).
Problem mapProblem(std::shared_ptr<const geometry::OccupancyGrid> map, bool allow_unknown = false);

/// roomProblem() of a world file (config/roomba_world.yaml format). Throws util::InvalidInput
/// naming the file and the bad parameter (world::loadWorld()).
Problem loadRoom(const std::string& world_file);

}  // namespace roomba_rrt::planning
