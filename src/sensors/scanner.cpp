// Scheduling and taking scans (scanner.h).
#include "roomba_rrt/sensors/scanner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomba_rrt::sensors {

namespace {
/// Slack on the schedule: a step time that rounds just below n / rate still takes scan n.
constexpr double kTimeSlack = 1e-9;
}  // namespace

RayFan::RayFan(const RangeSensorSpec& spec) {
  for (int k = 0; k < spec.samples; ++k) {
    const double angle = spec.angle_min + k * spec.angleIncrement();
    cos.push_back(std::cos(angle));
    sin.push_back(std::sin(angle));
  }
}

void measure(const RayCaster& caster, const RangeSensorSpec& spec, const RayFan& fan,
             const robot::Pose2D& pose, const std::vector<geometry::Circle>& others,
             std::mt19937& noise, std::vector<float>& ranges) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  Ray ray;
  ray.origin = {pose.x + c * spec.mount.x - s * spec.mount.y,
                pose.y + s * spec.mount.x + c * spec.mount.y};
  const double heading = pose.theta + spec.mount.theta;
  const double ch = std::cos(heading), sh = std::sin(heading);
  std::normal_distribution<double> gauss(0.0, spec.noise_stddev);
  ranges.resize(static_cast<std::size_t>(spec.samples));
  for (int k = 0; k < spec.samples; ++k) {
    ray.dx = ch * fan.cos[k] - sh * fan.sin[k];
    ray.dy = sh * fan.cos[k] + ch * fan.sin[k];
    double range = caster.cast(ray, spec.range_max, others);
    if (range < spec.range_min) {
      ranges[k] = -kInf;
      continue;
    }
    if (range <= spec.range_max && spec.noise_stddev > 0) {
      range = std::clamp(range + gauss(noise), spec.range_min, spec.range_max);
    }
    ranges[k] = static_cast<float>(range);
  }
}

namespace {
/// The room to cast in: the world's, or (no sensors at all) an empty one, so that a large map
/// does not cost its clearance for nothing.
world::Room castingRoom(const world::World& world) {
  for (const world::RobotSpec& robot : world.robots) {
    if (!robot.sensors.empty()) return world.room;
  }
  return {};
}
}  // namespace

Scanner::Scanner(const world::World& world) : caster_(castingRoom(world)) {
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    radii_.push_back(world.robots[r].radius);
    const auto& specs = world.robots[r].sensors;
    for (std::size_t k = 0; k < specs.size(); ++k) {
      sensors_.push_back({r, k, specs[k], RayFan(specs[k]), std::mt19937(specs[k].seed), 0.0});
    }
  }
}

const std::vector<Scan>& Scanner::scan(double time, const std::vector<robot::Pose2D>& poses) {
  scans_.clear();
  for (Sensor& sensor : sensors_) {
    if (time + kTimeSlack < sensor.next_time) continue;
    sensor.next_time = (std::floor((time + kTimeSlack) * sensor.spec.rate) + 1) / sensor.spec.rate;
    others_.clear();
    for (std::size_t r = 0; r < poses.size(); ++r) {
      if (r != sensor.robot) others_.push_back({{poses[r].x, poses[r].y}, radii_[r]});
    }
    Scan& out = scans_.emplace_back();
    out.robot = sensor.robot;
    out.sensor = sensor.index;
    out.time = time;
    measure(caster_, sensor.spec, sensor.fan, poses[sensor.robot], others_, sensor.noise,
            out.ranges);
    rays_ += out.ranges.size();
  }
  return scans_;
}

}  // namespace roomba_rrt::sensors
