#include "roomba_rrt/world_planning/room_problem.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::world_planning {

planning::Problem roomProblem(const world::World& world) {
  planning::Problem p = world.room.map ? planning::mapProblem(world.room.map) : planning::Problem{};
  p.bounds = {world.room.origin.x, world.room.origin.x + world.room.width, world.room.origin.y,
              world.room.origin.y + world.room.height};
  p.obstacles = world.room.circles;
  p.rectangles = world.room.rectangles;
  p.robot_radius = world.robot().radius;
  p.start = p.goal = {world.robot().initial_pose.x, world.robot().initial_pose.y};
  return p;
}

planning::Problem loadRoom(const std::string& world_file) {
  return roomProblem(world::loadWorld(world_file));
}

}  // namespace roomba_rrt::world_planning
