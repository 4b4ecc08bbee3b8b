// The ranges of input the planning library supports; validate() refuses everything else.
//
// Within them every quantity the planners compute stays finite and precise: squared distances
// (at most about 10^13) never overflow, a grid cell is never narrower than a double can resolve,
// and cell indices come from finite numbers. Outside them the arithmetic breaks down (a bound
// span of 1.6e308 overflows to +inf, a width of 1e-320 makes a cell's inverse width +inf).
#pragma once

namespace roomba_rrt::planning {

/// Every coordinate (start, goal, bounds, obstacle centres) lies in [-kMaxCoordinate,
/// kMaxCoordinate] metres.
inline constexpr double kMaxCoordinate = 1e6;
/// The bounds' width (x_max - x_min) and height (y_max - y_min) are at least this (m); at most
/// 2 kMaxCoordinate follows from the coordinates.
inline constexpr double kMinBoundsExtent = 1e-6;
/// The step lies in [kMinStep, kMaxLength] metres.
inline constexpr double kMinStep = 1e-6;
/// The largest step, goal tolerance and obstacle radius (m).
inline constexpr double kMaxLength = 1e6;
/// At most this many obstacles per query (each is checked on every sample and step).
inline constexpr int kMaxObstacles = 10000;
/// max_planning_time lies in [0, kMaxPlanningTime] seconds (0: no limit).
inline constexpr double kMaxPlanningTime = 3600;

}  // namespace roomba_rrt::planning
