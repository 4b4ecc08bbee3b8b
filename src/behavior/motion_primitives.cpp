#include "roomba_rrt/behavior/motion_primitives.h"

#include <cmath>

namespace roomba_rrt::behavior {

double Rotate::drawAngle(std::mt19937& rng) {
  constexpr double kPi = 3.14159265358979323846;
  const double u = static_cast<double>(rng()) * 0x1p-32;  // exactly representable, in [0, 1)
  return -kPi + 2.0 * kPi * u;
}

void TurnInPlace::start(double angle) {
  const double magnitude = std::fabs(angle);
  const double per_tick = speed_ * dt_;
  const long n = static_cast<long>(std::ceil(magnitude / per_tick));
  const double sign = angle < 0 ? -1.0 : 1.0;
  full_ = sign * speed_;
  last_ = n > 0 ? sign * (magnitude - static_cast<double>(n - 1) * per_tick) / dt_ : 0.0;
  timer_.setLength(n);
  timer_.restart();
}

}  // namespace roomba_rrt::behavior
