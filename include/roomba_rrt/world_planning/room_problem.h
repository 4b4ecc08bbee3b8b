// A world as a planning problem: what the planner is asked to plan in when the robot plans in the
// room it lives in (scenario `room`, the navigation tree, the tools). Above both the world (its
// walls, furniture, map and robot) and the planning library, which knows neither files nor robots.
#pragma once

#include <string>

#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::world_planning {

/// The simulator's room as a planning problem (scenario `room`): bounds = the room's walls (a
/// map's extent), obstacles = its furniture (circles and rectangles) and its map's occupied and
/// unknown cells, robot_radius = the world's robot, start and goal = the robot's initial position
/// (callers set their own).
planning::Problem roomProblem(const world::World& world);

/// roomProblem() of a world file (config/roomba_world.yaml format). Throws util::InvalidInput
/// naming the file and the bad parameter (world::loadWorld()).
planning::Problem loadRoom(const std::string& world_file);

}  // namespace roomba_rrt::world_planning
