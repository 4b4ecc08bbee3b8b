// Range sensors' presets and rules (range_sensor.h).
#include "roomba_rrt/sensors/range_sensor.h"

#include <cctype>
#include <cmath>
#include <set>

#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::sensors {

namespace {

using util::InvalidInput;
using util::member;

constexpr double kPi = 3.14159265358979323846;

/// A ROS graph name without slashes: a topic under the robot's namespace, a frame under its
/// tf prefix.
bool isPlainName(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

}  // namespace

RangeSensorSpec ldsPreset() {
  RangeSensorSpec lds;
  lds.name = "scan";
  lds.frame = "base_scan";
  lds.samples = 360;
  lds.angle_min = 0;
  lds.angle_max = 2 * kPi * 359 / 360;
  lds.range_min = 0.12;
  lds.range_max = 3.5;
  lds.rate = 5;
  return lds;
}

RangeSensorSpec irBumperPreset(double robot_radius) {
  RangeSensorSpec ir;
  ir.name = "ir_bumper";
  ir.frame = "base_ir_bumper";
  ir.mount = {robot_radius, 0, 0};
  ir.samples = 6;
  ir.angle_min = -70 * kPi / 180;
  ir.angle_max = 70 * kPi / 180;
  ir.range_min = 0;
  ir.range_max = 0.15;
  ir.rate = 20;
  return ir;
}

RangeSensorSpec preset(const std::string& name, double robot_radius, const std::string& field) {
  if (name == "lds") return ldsPreset();
  if (name == "ir_bumper") return irBumperPreset(robot_radius);
  throw InvalidInput(field, "must be lds or ir_bumper, got '" + name + "'");
}

void validate(const RangeSensorSpec& s, const std::string& prefix, double robot_radius,
              double step) {
  for (const auto& [key, value] : {std::pair{"name", &s.name}, {"frame", &s.frame}}) {
    if (!isPlainName(*value)) {
      throw InvalidInput(
          member(prefix, key),
          "must start with a letter and hold only letters, digits and '_', got '" + *value + "'");
    }
  }
  util::requireInRange(member(prefix, "samples"), s.samples, 1, SensorLimits::kMaxSamples);
  util::requireInRange(member(prefix, "angle_min"), s.angle_min, -2 * kPi, 2 * kPi, "rad");
  util::requireInRange(member(prefix, "angle_max"), s.angle_max, s.angle_min, s.angle_min + 2 * kPi,
                       "rad");
  util::requireInRange(member(prefix, "range_min"), s.range_min, 0.0, SensorLimits::kMaxRange, "m");
  if (!(s.range_max > s.range_min)) {
    throw InvalidInput(member(prefix, "range_max"), "must be greater than range_min (" +
                                                        util::show(s.range_min) + "), got " +
                                                        util::show(s.range_max));
  }
  util::requirePositive(member(prefix, "range_max"), s.range_max, SensorLimits::kMaxRange, "m");
  util::requirePositive(member(prefix, "rate"), s.rate, 1 / step,
                        "Hz (the simulator's step rate, 1 / step)");
  util::requireInRange(member(prefix, "noise_stddev"), s.noise_stddev, 0.0, SensorLimits::kMaxNoise,
                       "m");
  for (const auto& [key, value] :
       {std::pair{"x", s.mount.x}, {"y", s.mount.y}, {"yaw", s.mount.theta}}) {
    util::requireFinite(member(prefix, key), value);
  }
  const double offset = std::hypot(s.mount.x, s.mount.y);
  if (offset > robot_radius) {
    throw InvalidInput(member(prefix, "x"),
                       "(" + util::show(s.mount.x) + ", " + util::show(s.mount.y) +
                           ") is outside the robot's disc: at most " + util::show(robot_radius) +
                           " m from its centre, got " + util::show(offset));
  }
}

void validate(const std::vector<RangeSensorSpec>& sensors, const std::string& prefix,
              double robot_radius, double step) {
  if (sensors.size() > SensorLimits::kMaxSensors) {
    throw InvalidInput(prefix, "has " + std::to_string(sensors.size()) + " entries; at most " +
                                   std::to_string(SensorLimits::kMaxSensors) + " are supported");
  }
  std::set<std::string> names, frames;
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const std::string field = util::entry(prefix, k);
    validate(sensors[k], field, robot_radius, step);
    if (!names.insert(sensors[k].name).second) {
      throw InvalidInput(member(field, "name"), "repeats '" + sensors[k].name + "'");
    }
    if (!frames.insert(sensors[k].frame).second) {
      throw InvalidInput(member(field, "frame"), "repeats '" + sensors[k].frame + "'");
    }
  }
}

}  // namespace roomba_rrt::sensors
