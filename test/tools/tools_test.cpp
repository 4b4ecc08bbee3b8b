// The tools' shared flags and statistics as a user meets them: messages naming the flag.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../src/tools/tool_arguments.h"
#include "roomba_rrt/util/statistics.h"

namespace roomba_rrt::tools {
namespace {

/// The message of the std::invalid_argument `f` throws, or "" when it does not.
template <typename F>
std::string refusal(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ToolArguments, numbers_must_be_whole_and_finite_and_the_message_names_the_flag) {
  EXPECT_DOUBLE_EQ(parseDoubleFlag("--step", "0.25"), 0.25);
  EXPECT_EQ(parseIntFlag("--runs", "200"), 200);
  EXPECT_EQ(refusal([] { parseDoubleFlag("--step", "0.2x"); }),
            "--step: expected a number, got '0.2x'");
  EXPECT_EQ(refusal([] { parseDoubleFlag("--step", "inf"); }), "--step: expected a finite number");
  EXPECT_EQ(refusal([] { parseIntFlag("--runs", "2.5"); }),
            "--runs: expected an integer, got '2.5'");
}

TEST(ToolArguments, planner_flags_are_parsed_and_the_scenario_file_defaults_to_the_config) {
  const char* argv[] = {"rrt_plot", "--algorithm", "rrt_connect", "--seed",
                        "7",        "--smooth",    "-o",          "a.png"};
  const ToolArguments args = parseToolArguments(8, argv, {"-o"}, {});
  EXPECT_EQ(args.options.algorithm, planning::Algorithm::kRrtConnect);
  EXPECT_EQ(args.options.seed, 7u);
  EXPECT_TRUE(args.options.smooth);
  EXPECT_EQ(args.tool.at("-o"), "a.png");
  EXPECT_EQ(args.scenario_file, defaultScenarioFile());
  EXPECT_TRUE(std::ifstream(defaultScenarioFile()).good()) << defaultScenarioFile();
  const char* unknown[] = {"rrt_plot", "--bogus", "1"};
  EXPECT_EQ(refusal([&] { parseToolArguments(3, unknown, {}, {}); }), "--bogus: unknown flag");
}

TEST(Statistics, mean_and_sample_deviation_as_matlab_nan_where_undefined) {
  const auto [mean, std] = util::meanAndStd({1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(mean, 2.5);
  EXPECT_DOUBLE_EQ(std, std::sqrt(5.0 / 3.0));  // N - 1
  EXPECT_DOUBLE_EQ(util::meanAndStd({7}).first, 7);
  EXPECT_TRUE(std::isnan(util::meanAndStd({7}).second));
  EXPECT_TRUE(std::isnan(util::meanAndStd({}).first));
}

}  // namespace
}  // namespace roomba_rrt::tools
