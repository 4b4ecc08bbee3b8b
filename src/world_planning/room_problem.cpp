#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::world_planning {

planning::Problem roomProblem(const world::World& world) {
  planning::Problem p = world.map ? planning::mapProblem(world.map) : planning::Problem{};
  p.bounds = {world.origin.x, world.origin.x + world.width, world.origin.y,
              world.origin.y + world.height};
  p.obstacles = world.circles;
  p.rectangles = world.rectangles;
  p.robot_radius = world.robot_radius;
  p.start = p.goal = {world.initial_pose.x, world.initial_pose.y};
  return p;
}

planning::Problem loadRoom(const std::string& world_file) {
  return roomProblem(world::loadWorld(world_file));
}

}  // namespace roomba_rrt::world_planning
