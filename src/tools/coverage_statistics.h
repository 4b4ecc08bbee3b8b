// roomba_coverage's statistics over seeds: the typical seed, "mean ± std" as the tables print it,
// and the band of the --plot curves. Means and deviations are util::meanAndStd's.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace roomba_rrt::tools {

/// Index of the value closest to the mean (the first of equals): a typical run, not the worst.
std::size_t closestToMean(const std::vector<double>& values);

/// Fractions as "mean ± std" in percent, one decimal ("48.9 ± 4.5"; the mean right-aligned in
/// five characters); just the mean for one value.
std::string percentMeanStd(const std::vector<double>& values);

/// Every seed's runs with one robot count (or of one behaviour: --compare).
struct FleetStatistics {
  int robots = 0;
  std::string label;                    ///< the curve's name in a plot's legend; "" for "N robots"
  std::vector<std::vector<double>> at;  ///< [checkpoint][seed]
  std::vector<double> finals;           ///< [seed]
  std::vector<std::vector<double>> curves;  ///< [seed][point]
};

/// The mean over the seeds at each point of equally long curves, and the standard deviation
/// (0 for one seed).
struct Band {
  std::vector<double> mean, std;
};
Band bandOf(const std::vector<std::vector<double>>& curves);

}  // namespace roomba_rrt::tools
