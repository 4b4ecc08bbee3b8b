#include "coverage_statistics.h"

#include <cmath>
#include <cstdio>

#include "roomba_rrt/util/statistics.h"

namespace roomba_rrt::tools {

std::size_t closestToMean(const std::vector<double>& values) {
  const double mean = util::meanAndStd(values).first;
  std::size_t best = 0;
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (std::abs(values[i] - mean) < std::abs(values[best] - mean)) best = i;
  }
  return best;
}

std::string percentMeanStd(const std::vector<double>& values) {
  const auto [mean, std] = util::meanAndStd(values);
  char text[64];
  if (values.size() < 2) {
    std::snprintf(text, sizeof text, "%5.1f", 100 * mean);
  } else {
    std::snprintf(text, sizeof text, "%5.1f ± %.1f", 100 * mean, 100 * std);
  }
  return text;
}

Band bandOf(const std::vector<std::vector<double>>& curves) {
  const std::size_t points = curves.front().size();
  Band band{std::vector<double>(points), std::vector<double>(points)};
  std::vector<double> values;
  for (std::size_t p = 0; p < points; ++p) {
    values.clear();
    for (const auto& curve : curves) values.push_back(curve[p]);
    const auto [mean, std] = util::meanAndStd(values);
    band.mean[p] = mean;
    band.std[p] = values.size() > 1 ? std : 0.0;
  }
  return band;
}

}  // namespace roomba_rrt::tools
