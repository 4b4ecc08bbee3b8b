// The lab's scenarios, read from config/rrt_scenarios.yaml, and the simulator's room.
#pragma once

#include <map>
#include <string>

#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::planning {

/// Reads a scenario file (see config/rrt_scenarios.yaml for the format). Throws
/// util::InvalidInput naming the file and the field on a malformed file.
std::map<std::string, Problem> loadScenarios(const std::string& path);

/// The simulator's room as a planning problem (scenario `room`): bounds = the room's walls,
/// obstacles = its furniture (circles and rectangles), robot_radius = the world's robot, start and
/// goal = the robot's initial position (callers set their own). A world that is a map is refused
/// (util::InvalidInput naming `map`): the planner does not plan on occupancy grids yet.
Problem roomProblem(const world::World& world);

/// roomProblem() of a world file (config/roomba_world.yaml format). Throws util::InvalidInput
/// naming the file and the bad parameter (world::loadWorld()).
Problem loadRoom(const std::string& world_file);

}  // namespace roomba_rrt::planning
