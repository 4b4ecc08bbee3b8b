// Summary statistics of repeated runs, shared by the planning core's Monte Carlo and the tools.
#pragma once

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace roomba_rrt::util {

/// Mean and sample standard deviation (N − 1), as MATLAB's mean() and std(); NaN where
/// undefined (the mean of nothing, the deviation of fewer than two values).
inline std::pair<double, double> meanAndStd(const std::vector<double>& values) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (values.empty()) return {kNaN, kNaN};
  double sum = 0;
  for (double v : values) sum += v;
  const double mean = sum / values.size();
  if (values.size() < 2) return {mean, kNaN};
  double squares = 0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / (values.size() - 1))};
}

}  // namespace roomba_rrt::util
