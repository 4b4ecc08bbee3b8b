// The ROS interface of the coverage_planner node over the ROS-free coverage planner: a
// PlanCoverage request (fields left at zero take the node's defaults) becomes a world and
// coverage::CoverageOptions, and the plan becomes the response: one nav_msgs/Path of rows and
// transits in driving order, the index of each row's start, lengths and areas.
#pragma once

#include <memory>
#include <string>

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <roomba_rrt/PlanCoverage.h>
#include <roomba_rrt/coverage/coverage_planner.h>
#include <roomba_rrt/world/world.h>

namespace roomba_rrt::coverage_node {

/// What the node plans in and with, for every request field left at zero or empty.
struct CoverageDefaults {
  /// world "room" (or ""): ~world_file's world.
  std::shared_ptr<const world::World> room;
  /// world "map": the latest map on ~map_topic as a world (mapWorld), nullptr until one arrives.
  std::shared_ptr<const world::World> map;
  double clearance = coverage::CoverageOptions().clearance;  ///< ~clearance (m)
  std::string frame_id = "map";                              ///< the path's frame
};

/// Answers `request`: success with the plan, or success false and a message naming the field
/// ("start: ...", "x_min..y_max: ...", "swath: ..."). Never throws on bad input. Plans from
/// scratch (sampling the world) at each call: a few milliseconds for a room, seconds for a
/// whole building's map.
/// `planned_in` (optional) gets the world the plan was made in (the request's world, region and
/// robot), when the request is valid.
PlanCoverage::Response planCoverage(const PlanCoverage::Request& request,
                                    const CoverageDefaults& defaults, const ros::Time& stamp,
                                    world::World* planned_in = nullptr);

/// The plan's legs as one path in `frame_id`: each transit's and row's points in order (the
/// point where one leg meets the next once), each pose facing along the path; `row_starts` gets
/// the index of the first pose of each segment of a row (a row of no length has none).
nav_msgs::Path toPathMessage(const coverage::CoveragePlan& plan, const std::string& frame_id,
                             const ros::Time& stamp, std::vector<std::uint32_t>* row_starts);

/// The answer drawn for rviz (after a DELETEALL): the rows (ns `rows`, one LINE_LIST, green),
/// the transits between them (ns `transits`, one LINE_LIST, orange, thinner), each row's start
/// (ns `row_starts`, POINTS) and the start (ns `start`, a sphere); with `world` (the one it was
/// planned in) also its room's walls (ns `room`, LINE_STRIP) and furniture (ns `furniture`, flat
/// grey cylinders and boxes; a map's cells are rviz's Map display's). Nothing but the DELETEALL
/// for an answer without a path.
visualization_msgs::MarkerArray toMarkers(const PlanCoverage::Response& answer,
                                          const world::World* world = nullptr);

}  // namespace roomba_rrt::coverage_node
