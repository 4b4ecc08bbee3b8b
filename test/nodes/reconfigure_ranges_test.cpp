// One source of truth for ranges: every dynamic_reconfigure range (cfg/*.cfg, as generated) is
// the range the node validates. For each parameter the .cfg's minimum and maximum are accepted by
// the core's validation (or, for an open end such as forward_speed > 0, refused: the node then
// keeps the value in force), and a value just outside them is refused. A .cfg edited without the
// C++ limits (or the other way round) fails here.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <roomba_rrt/NavFollowerConfig.h>
#include <roomba_rrt/RoombaBehaviorConfig.h>
#include <roomba_rrt/RoombaSimConfig.h>
#include <roomba_rrt/RrtPlannerConfig.h>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/planning/planner.h"
#include "roomba_rrt/planning/validate.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt {
namespace {

/// Whether `check` accepts `value` (it throws std::invalid_argument to refuse).
bool accepts(const std::function<void(double)>& check, double value) {
  try {
    check(value);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

/// Just beyond `bound`, away from the range.
double below(double bound) { return bound - std::max(1e-9, std::fabs(bound) * 1e-9); }
double above(double bound) { return bound + std::max(1e-9, std::fabs(bound) * 1e-9); }

enum class End { kClosed, kOpen };

/// The .cfg range [min, max] of `name` is the validated one: each end accepted when closed
/// (refused when open), and a value just outside each end refused (`gap` outside for an
/// integer, 1).
void expectSameRange(const std::string& name, double min, double max,
                     const std::function<void(double)>& check, End low = End::kClosed,
                     End high = End::kClosed, double gap = 0) {
  SCOPED_TRACE(name);
  EXPECT_EQ(accepts(check, min), low == End::kClosed) << "min " << min;
  EXPECT_EQ(accepts(check, max), high == End::kClosed) << "max " << max;
  EXPECT_FALSE(accepts(check, gap > 0 ? min - gap : below(min))) << "just below min " << min;
  EXPECT_FALSE(accepts(check, gap > 0 ? max + gap : above(max))) << "just above max " << max;
  EXPECT_TRUE(accepts(check, 0.5 * (min + max))) << "the middle";
}

TEST(ReconfigureRanges, roomba_behavior_cfg_is_roomba_param_limits) {
  using C = RoombaBehaviorConfig;
  const C& lo = C::__getMin__();
  const C& hi = C::__getMax__();
  const auto field = [](double behavior::RoombaParams::*member) {
    return [member](double v) {
      behavior::RoombaParams p;
      p.*member = v;
      behavior::validate(p);
    };
  };
  using P = behavior::RoombaParams;
  expectSameRange("move_forward_time", lo.move_forward_time, hi.move_forward_time,
                  field(&P::move_forward_time));
  expectSameRange("move_in_spiral_time", lo.move_in_spiral_time, hi.move_in_spiral_time,
                  field(&P::move_in_spiral_time));
  expectSameRange("go_back_time", lo.go_back_time, hi.go_back_time, field(&P::go_back_time));
  expectSameRange("forward_speed", lo.forward_speed, hi.forward_speed, field(&P::forward_speed),
                  End::kOpen);
  expectSameRange("backward_speed", lo.backward_speed, hi.backward_speed, field(&P::backward_speed),
                  End::kClosed, End::kOpen);
  expectSameRange("angular_speed", lo.angular_speed, hi.angular_speed, field(&P::angular_speed),
                  End::kOpen);
  expectSameRange("initial_radius_spiral", lo.initial_radius_spiral, hi.initial_radius_spiral,
                  field(&P::initial_radius_spiral), End::kOpen);
  expectSameRange("spiral_factor", lo.spiral_factor, hi.spiral_factor, field(&P::spiral_factor));
}

TEST(ReconfigureRanges, roomba_sim_cfg_is_world_limits) {
  using C = RoombaSimConfig;
  const C& lo = C::__getMin__();
  const C& hi = C::__getMax__();
  // A world where a speed limit is bounded only by its range: the smallest step, a large robot.
  world::World base;
  base.step = world::WorldLimits::kMinStep;
  const auto robot = [base](double world::RobotSpec::*member) {
    return [base, member](double v) {
      world::World w = base;
      w.robot().*member = v;
      world::validate(w);
    };
  };
  const auto setting = [](double world::SimulatorSettings::*member) {
    return [member](double v) {
      world::SimulatorSettings s;
      s.*member = v;
      world::validate(s);
    };
  };
  expectSameRange("real_time_factor", lo.real_time_factor, hi.real_time_factor,
                  setting(&world::SimulatorSettings::real_time_factor));
  expectSameRange("command_timeout", lo.command_timeout, hi.command_timeout,
                  setting(&world::SimulatorSettings::command_timeout), End::kOpen);
  expectSameRange("max_linear_speed", lo.max_linear_speed, hi.max_linear_speed,
                  robot(&world::RobotSpec::max_linear_speed), End::kOpen);
  expectSameRange("max_angular_speed", lo.max_angular_speed, hi.max_angular_speed,
                  robot(&world::RobotSpec::max_angular_speed), End::kOpen);
}

TEST(ReconfigureRanges, nav_follower_cfg_is_follower_limits) {
  using C = NavFollowerConfig;
  const C& lo = C::__getMin__();
  const C& hi = C::__getMax__();
  // The node refuses values below FollowerLimits::kMin at start; validate() has the maxima.
  const auto field = [](double navigation::FollowerParams::*member) {
    return [member](double v) {
      if (!(v >= navigation::FollowerLimits::kMin)) throw std::invalid_argument("below kMin");
      navigation::FollowerParams p;
      p.*member = v;
      p.max_deviation = std::max(p.max_deviation, 2 * p.xy_tolerance);  // the rule between them
      navigation::validate(p);
    };
  };
  using P = navigation::FollowerParams;
  expectSameRange("max_linear_speed", lo.max_linear_speed, hi.max_linear_speed,
                  field(&P::max_linear_speed));
  expectSameRange("max_angular_speed", lo.max_angular_speed, hi.max_angular_speed,
                  field(&P::max_angular_speed));
  expectSameRange("xy_tolerance", lo.xy_tolerance, hi.xy_tolerance, field(&P::xy_tolerance));
  expectSameRange("yaw_tolerance", lo.yaw_tolerance, hi.yaw_tolerance, field(&P::yaw_tolerance));
}

TEST(ReconfigureRanges, rrt_planner_cfg_is_the_planning_librarys_validation) {
  using C = RrtPlannerConfig;
  const C& lo = C::__getMin__();
  const C& hi = C::__getMax__();
  // The node's defaults: the lab's start, goal and bounds; a robot of any size fits in bounds as
  // wide as the coordinates allow.
  planning::Problem base;
  base.start = {1, 1};
  base.goal = {9, 9};
  const auto option = [base](auto member) {
    return [base, member](double v) {
      planning::PlannerOptions o;
      o.max_planning_time = 5;
      o.*member = static_cast<std::remove_reference_t<decltype(o.*member)>>(v);
      if (!(o.max_planning_time > 0)) throw std::invalid_argument("max_planning_time: > 0");
      planning::validate(base, o, planning::kDefaultMaxIterationsCap);
    };
  };
  using O = planning::PlannerOptions;
  expectSameRange("step", lo.step, hi.step, option(&O::step));
  expectSameRange("goal_bias", lo.goal_bias, hi.goal_bias, option(&O::goal_bias));
  expectSameRange("max_iterations", lo.max_iterations, hi.max_iterations,
                  option(&O::max_iterations), End::kClosed, End::kClosed, /*gap=*/1);
  expectSameRange("goal_tolerance", lo.goal_tolerance, hi.goal_tolerance,
                  option(&O::goal_tolerance));
  expectSameRange("max_planning_time", lo.max_planning_time, hi.max_planning_time,
                  option(&O::max_planning_time), End::kOpen);
  const auto size = [base](double planning::Problem::*member) {
    return [base, member](double v) {
      planning::Problem p = base;
      p.bounds = {-planning::kMaxCoordinate, planning::kMaxCoordinate, -planning::kMaxCoordinate,
                  planning::kMaxCoordinate};
      p.start = {0, 0};
      p.goal = {1, 1};
      p.*member = v;
      planning::PlannerOptions o;
      o.max_planning_time = 5;
      planning::validate(p, o, planning::kDefaultMaxIterationsCap);
    };
  };
  // A disc as large as the range allows does not fit round the start in any bounds: only the
  // lower end and the middle are the range's business; the upper end is "fits in the bounds".
  EXPECT_TRUE(accepts(size(&planning::Problem::robot_radius), lo.robot_radius));
  EXPECT_FALSE(accepts(size(&planning::Problem::robot_radius), below(lo.robot_radius)));
  EXPECT_EQ(hi.robot_radius, planning::kMaxLength);
  EXPECT_TRUE(accepts(size(&planning::Problem::clearance), lo.clearance));
  EXPECT_FALSE(accepts(size(&planning::Problem::clearance), below(lo.clearance)));
  EXPECT_EQ(hi.clearance, planning::kMaxLength);
}

TEST(ReconfigureRanges, rrt_planner_choices_are_the_librarys_names) {
  // The enum's values of cfg/RrtPlanner.cfg parse; the defaults are the library's.
  for (const char* name : {"rrt", "rrt_connect", "rrt_star"}) {
    EXPECT_TRUE(planning::parseAlgorithm(name).has_value()) << name;
  }
  for (const char* name : {"points", "segments"}) {
    EXPECT_TRUE(planning::parseCollisionCheck(name).has_value()) << name;
  }
  const RrtPlannerConfig& d = RrtPlannerConfig::__getDefault__();
  EXPECT_EQ(d.algorithm, planning::toString(planning::PlannerOptions{}.algorithm));
  EXPECT_EQ(d.collision_check, planning::toString(planning::PlannerOptions{}.collision));
  EXPECT_EQ(d.step, planning::PlannerOptions{}.step);
}

}  // namespace
}  // namespace roomba_rrt
