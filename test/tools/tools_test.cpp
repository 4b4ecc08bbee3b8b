// The tools' shared flags and statistics, and roomba_coverage's arguments and statistics, as a
// user meets them: messages naming the flag, the numbers the tables print.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../src/tools/coverage_arguments.h"
#include "../../src/tools/coverage_statistics.h"
#include "../../src/tools/tool_arguments.h"
#include "../common/shared_maps.h"
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

TEST(ToolArguments, world_names_the_package_rooms_as_scripts_run_does) {
  EXPECT_EQ(worldFile("furnished"), ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  EXPECT_EQ(worldFile("empty"), ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");
  EXPECT_EQ(worldFile("my/world.yaml"), "my/world.yaml");
  const char* argv[] = {"roomba_coverage", "--behavior", "fsm", "--world", "furnished"};
  EXPECT_EQ(parseCoverageArguments(5, argv).world,
            ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  EXPECT_NE(std::string(coverageUsage()).find("needs --robots"), std::string::npos);
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

TEST(CoverageStatistics, tables_print_percent_mean_and_std_with_one_decimal) {
  EXPECT_EQ(percentMeanStd({0.45, 0.55}), " 50.0 ± 7.1");
  EXPECT_EQ(percentMeanStd({0.637}), " 63.7") << "one run: no deviation";
}

TEST(CoverageStatistics, the_typical_seed_is_the_one_closest_to_the_mean) {
  EXPECT_EQ(closestToMean({0.9, 0.5, 0.45, 0.2}), 1u);  // mean 0.5125
  EXPECT_EQ(closestToMean({0.25, 0.75}), 0u) << "the first of equals";
}

TEST(CoverageStatistics, the_band_of_one_seed_has_no_width) {
  const Band one = bandOf({{0.1, 0.2, 0.3}});
  EXPECT_EQ(one.mean, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(one.std, (std::vector<double>{0, 0, 0}));
  const Band two = bandOf({{0.1, 0.2}, {0.3, 0.2}});
  EXPECT_DOUBLE_EQ(two.mean[0], 0.2);
  EXPECT_NEAR(two.std[0], std::sqrt(0.02), 1e-15);
  EXPECT_EQ(two.std[1], 0.0);
}

CoverageArguments parse(std::vector<const char*> args) {
  args.insert(args.begin(), "roomba_coverage");
  return parseCoverageArguments(static_cast<int>(args.size()), args.data());
}

TEST(CoverageArguments, coverage_is_a_behaviour_and_compare_runs_all_three) {
  EXPECT_EQ(parse({"--behavior", "coverage"}).behavior, "coverage");
  EXPECT_EQ(parse({"--behavior", "coverage", "--tree", "t.xml"}).tree, "t.xml");
  const CoverageArguments o = parse({"--compare", "--seeds", "3", "--plot", "p.png"});
  EXPECT_TRUE(o.compare);
  EXPECT_TRUE(o.behavior.empty());
  EXPECT_EQ(o.seeds, 3);
  EXPECT_EQ(o.plot, "p.png");
}

TEST(CoverageArguments, defaults_are_the_lab_run_in_the_config_room) {
  const CoverageArguments o = parse({"--behavior", "fsm"});
  EXPECT_EQ(o.duration, 600);
  EXPECT_EQ(o.seed, 1u);
  EXPECT_EQ(o.seeds, 1);
  EXPECT_TRUE(std::ifstream(o.world).good()) << o.world;
  EXPECT_TRUE(std::ifstream(o.config).good()) << o.config;
  EXPECT_TRUE(o.robots.empty());
  EXPECT_TRUE(parse({"--help"}).help);
}

TEST(CoverageArguments, robot_counts_are_a_list_of_whole_numbers) {
  EXPECT_EQ(parse({"--behavior", "bt", "--robots", "1,2,4"}).robots, (std::vector<int>{1, 2, 4}));
  EXPECT_NE(refusal([] {
              parse({"--behavior", "bt", "--robots", "0"});
            }).find("--robots needs robot counts in [1, "),
            std::string::npos);
  EXPECT_NE(refusal([] {
              parse({"--behavior", "bt", "--robots", "2,x"});
            }).find("got '2,x'"),
            std::string::npos);
}

TEST(CoverageArguments, bad_values_and_combinations_are_refused_naming_the_flag) {
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "fsm", "--duration", "abc"});
            }),
            "--duration: expected a number, got 'abc'");
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "fsm", "--seed", "-1"});
            }),
            "--seed needs an integer in [0, 2^32), got -1");
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "fsm", "--seeds", "0"});
            }),
            "--seeds needs a positive integer, got 0");
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "walk"});
            }),
            "--behavior must be fsm, bt or coverage, got 'walk'");
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "fsm", "--tree", "t.xml"});
            }),
            "--tree needs --behavior bt or coverage");
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "fsm", "--robots", "2", "--png", "a.png"});
            }),
            "--csv and --png draw one robot; with --robots use --plot");
  EXPECT_EQ(refusal([] { parse({"--behavior"}); }), "--behavior needs a value");
  EXPECT_EQ(refusal([] {
              parse({"--compare", "--behavior", "bt"});
            }),
            "--compare runs fsm, bt and coverage: no --behavior, --tree, --csv, --png or --robots");
  EXPECT_EQ(refusal([] {
              parse({"--behavior", "coverage", "--robots", "2"});
            }),
            "--robots runs the lab's behaviours: fsm or bt");
}

TEST(ToolArguments, crop_keeps_a_region_of_the_world_whose_edges_become_walls) {
  const std::string apartment = worldFile("apartment");
  const roomba_rrt::world::World whole = loadToolWorld(apartment, "");
  const roomba_rrt::world::World part = loadToolWorld(apartment, "", "-2,-1.5,2,1.5");
  EXPECT_EQ(part.room.origin.x, -2.0);
  EXPECT_EQ(part.room.origin.y, -1.5);
  EXPECT_EQ(part.room.width, 4.0);
  EXPECT_EQ(part.room.height, 3.0);
  ASSERT_TRUE(part.room.map);
  EXPECT_EQ(part.room.map_file, whole.room.map_file);  // the same grid, fewer rooms of it
  EXPECT_EQ(parse({"--behavior", "coverage", "--crop", "-1,-2,3,4"}).crop, "-1,-2,3,4");
  EXPECT_EQ(refusal([&] { loadToolWorld(apartment, "", "0,0,4"); }),
            "--crop: expected X0,Y0,X1,Y1, got '0,0,4'");
  EXPECT_NE(refusal([&] {
              loadToolWorld(apartment, "", "-1000,0,4,3");
            }).find("--crop: must lie within the world"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              loadToolWorld(apartment, "", "0,0,0.2,3");
            }).find("wider and higher than the robot"),
            std::string::npos);
}

TEST(ToolArguments, a_crop_of_a_large_map_gets_the_regions_coverage_cell) {
  // A 100 m x 100 m map gets 5 cm cells (the grid's limit); a few rooms of it, the usual 2.5 cm.
  ROOMBA_RRT_REQUIRE_SHARED_MAP("nav2_bench_100by100_15");
  const std::string map = ::roomba_rrt::test::sharedMapPath("nav2_bench_100by100_15");
  EXPECT_EQ(loadToolWorld(map, "14,14").coverage_cell_size, 0.05);
  EXPECT_EQ(loadToolWorld(map, "14,14", "10,10,17.5,17.5").coverage_cell_size, 0.025);
}

}  // namespace
}  // namespace roomba_rrt::tools
