// Contact between the robot's disc and the world: pushing the disc out of walls and furniture,
// and the bumper that contact closes.
#pragma once

#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sim {

/// Distance (m) within which a surface counts as touching the disc: the bumper reports contact
/// when the gap is at most this, so the rounding error of a push-back never releases it.
constexpr double kContactTolerance = 1e-6;

/// Pushes a disc of the world's robot radius centred at (x, y) out of every wall and piece of
/// furniture it penetrates, each time along that surface's normal (the lab's rule: no bounce, the
/// heading is not involved). Repeats until nothing is penetrated, which settles in one or two
/// passes even in a corner between furniture and a wall. Returns false, leaving (x, y) where the
/// last pass put it, when the disc does not fit at all there (a gap narrower than the robot);
/// callers then keep the previous position.
bool resolvePenetration(const world::World& world, double& x, double& y);

/// The same for a disc of radius `radius` (a named robot's own), in place of world.robot().radius.
bool resolvePenetration(const world::World& world, double radius, double& x, double& y);
robot::BumperState senseBumper(const world::World& world, double radius, const robot::Pose2D& pose);

/// Adds a contact in direction (nx, ny) from the centre of a robot at `pose` (any length) to
/// `bumper`, closing the switches as senseBumper does: another robot touching this one.
void pressBumper(robot::BumperState& bumper, const robot::Pose2D& pose, double nx, double ny);

/// The bumper of a robot at `pose`: pressed when any wall or piece of furniture touches the disc
/// (gap ≤ kContactTolerance). The side comes from the direction of each contact point seen from
/// the robot: left when it is on the +y side of the heading, right on the −y side, both when it is
/// within ±10° of the heading line (a head-on hit, as on a real Roomba).
robot::BumperState senseBumper(const world::World& world, const robot::Pose2D& pose);

}  // namespace roomba_rrt::sim
