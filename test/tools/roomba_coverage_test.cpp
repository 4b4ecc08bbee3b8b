// roomba_coverage as a user runs it: the picture of a many-seed run shows a typical seed (the
// one closest to the mean), and a progress bar appears on a terminal but never in a pipe.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "../common/run_node.h"

namespace {

using roomba_rrt::test::Outcome;
using roomba_rrt::test::runCommand;
using roomba_rrt::test::siblingExecutable;

Outcome coverage(const std::string& args) {
  return runCommand("timeout 60 " + siblingExecutable("roomba_coverage") + " " + args);
}

/// The coverage [%] the table prints for `seconds` ("       600    63.7 ± 13.3" → 63.7).
double coverageAt(const std::string& output, int seconds) {
  std::smatch m;
  const std::regex row("\\n +" + std::to_string(seconds) + " +([0-9.]+)");
  if (!std::regex_search(output, m, row)) return NAN;
  return std::stod(m[1]);
}

TEST(RoombaCoverage, png_of_many_seeds_draws_the_seed_closest_to_the_mean) {
  const std::string png = testing::TempDir() + "roomba_coverage_test.png";
  std::remove(png.c_str());
  const Outcome all = coverage("--behavior fsm --duration 600 --seed 1 --seeds 20 --png " + png);
  ASSERT_EQ(all.exit_code, 0) << all.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      all.output, m,
      std::regex("picture: .*, FSM, seed ([0-9]+), 600 s: ([0-9.]+) % of the floor cleaned "
                 "\\(closest to the mean of seeds 1–20, ([0-9.]+) %\\)")))
      << all.output;
  const int drawn = std::stoi(m[1]);
  const double drawn_coverage = std::stod(m[2]), mean_in_title = std::stod(m[3]);

  // Each seed on its own (one decimal, as printed).
  std::vector<double> each;
  for (int seed = 1; seed <= 20; ++seed) {
    const Outcome one = coverage("--behavior fsm --duration 600 --seed " + std::to_string(seed));
    ASSERT_EQ(one.exit_code, 0) << one.output;
    each.push_back(coverageAt(one.output, 600));
    ASSERT_FALSE(std::isnan(each.back())) << one.output;
  }
  double mean = 0;
  for (double c : each) mean += c / each.size();
  double closest = INFINITY;
  for (double c : each) closest = std::min(closest, std::abs(c - mean));

  EXPECT_NEAR(mean_in_title, mean, 0.1);
  EXPECT_NEAR(coverageAt(all.output, 600), mean, 0.1) << "the table's mean";
  EXPECT_DOUBLE_EQ(drawn_coverage, each[drawn - 1]) << "the title gives the drawn seed's coverage";
  EXPECT_LE(std::abs(each[drawn - 1] - mean), closest + 0.1)
      << "seed " << drawn << " (" << each[drawn - 1] << " %) is not the closest to the mean "
      << mean << " %";
  EXPECT_GT(std::abs(each[0] - mean), 10) << "seed 1 is no longer far from the mean: the test "
                                             "cannot tell a typical seed from the first";

  std::ifstream file(png, std::ios::binary);
  char magic[4] = {};
  file.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG") << png << " is not a PNG";
}

TEST(RoombaCoverage, progress_bar_on_a_terminal_only) {
  const std::string args = "--behavior bt --duration 60 --seeds 30";
  // `script` runs the tool on a pseudo-terminal, as in a user's shell.
  const Outcome terminal =
      runCommand("timeout 60 script -qec '" + siblingExecutable("roomba_coverage") + " " + args +
                 "' /dev/null");
  ASSERT_EQ(terminal.exit_code, 0) << terminal.output;
  EXPECT_NE(terminal.output.find("] 30/30 runs"), std::string::npos) << terminal.output;
  EXPECT_NE(terminal.output.find("\r[#"), std::string::npos) << terminal.output;

  const Outcome pipe = coverage(args);
  ASSERT_EQ(pipe.exit_code, 0) << pipe.output;
  EXPECT_EQ(pipe.output.find("/30 runs"), std::string::npos) << "a progress bar in a pipe";
  EXPECT_EQ(pipe.output.find('\r'), std::string::npos) << "control characters in a pipe";
  EXPECT_NEAR(coverageAt(pipe.output, 60), coverageAt(terminal.output, 60), 1e-9)
      << "the same table either way";
}

/// The union coverage [%] the --robots table prints for `robots` at its first column.
std::vector<double> fleetRow(const std::string& output, int robots) {
  std::smatch m;
  const std::regex row("\\n +" + std::to_string(robots) + "((?: +[0-9.]+(?: ± [0-9.]+)?)+)\\n");
  if (!std::regex_search(output, m, row)) return {};
  std::vector<double> values;
  const std::string cells = m[1];
  const std::regex number("([0-9.]+)(?: ± [0-9.]+)?");
  for (auto it = std::sregex_iterator(cells.begin(), cells.end(), number);
       it != std::sregex_iterator(); ++it) {
    values.push_back(std::stod((*it)[1]));
  }
  return values;
}

TEST(RoombaCoverage, one_robot_with_robots_1_is_the_lab_and_more_robots_clean_more) {
  const std::string plot = testing::TempDir() + "roomba_coverage_robots_test.png";
  std::remove(plot.c_str());
  const Outcome lab = coverage("--behavior fsm --duration 300 --seeds 5");
  ASSERT_EQ(lab.exit_code, 0) << lab.output;
  const Outcome fleets =
      coverage("--behavior fsm --duration 300 --seeds 5 --robots 1,2,4 --plot " + plot);
  ASSERT_EQ(fleets.exit_code, 0) << fleets.output;
  const std::vector<double> one = fleetRow(fleets.output, 1), two = fleetRow(fleets.output, 2),
                            four = fleetRow(fleets.output, 4);
  ASSERT_EQ(one.size(), 2u) << fleets.output;  // 60 s and 300 s
  ASSERT_EQ(two.size(), 2u) << fleets.output;
  ASSERT_EQ(four.size(), 2u) << fleets.output;
  EXPECT_EQ(one[0], coverageAt(lab.output, 60));
  EXPECT_EQ(one[1], coverageAt(lab.output, 300));
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_GT(two[c], one[c]);
    EXPECT_GT(four[c], two[c]);
  }
  std::ifstream png(plot, std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

TEST(RoombaCoverage, a_world_that_names_robots_runs_them_and_refuses_png) {
  const std::string world = std::string(ROOMBA_RRT_CONFIG_DIR) + "/roomba_world_two_robots.yaml";
  const Outcome two = coverage("--behavior bt --duration 60 --world " + world);
  ASSERT_EQ(two.exit_code, 0) << two.output;
  EXPECT_EQ(fleetRow(two.output, 2).size(), 1u) << two.output;
  const Outcome png = coverage("--behavior bt --duration 60 --png x.png --world " + world);
  EXPECT_EQ(png.exit_code, 2);
  EXPECT_NE(png.output.find("--plot"), std::string::npos) << png.output;
}

TEST(RoombaCoverage, coverage_reports_the_reachable_floor_and_compare_puts_all_three_side_by_side) {
  const Outcome one = coverage("--behavior coverage --world furnished --duration 420");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_NE(one.output.find("reachable floor 27.63 m² of 27.67 m² of floor"), std::string::npos)
      << one.output;
  EXPECT_NE(one.output.find("ideal time 162.5 s"), std::string::npos) << one.output;
  EXPECT_GT(coverageAt(one.output, 300), 95.0) << one.output;
  for (const char* row : {"(1.5× ideal)", "(2.0× ideal)", "(2.5× ideal)", "time to 90 % [s]",
                          "time to 95 % [s]", "time to 99 % [s]", "bumps per run"}) {
    EXPECT_NE(one.output.find(row), std::string::npos) << row << " not in\n" << one.output;
  }
  const std::string plot = testing::TempDir() + "roomba_coverage_compare.png";
  std::remove(plot.c_str());
  const Outcome all =
      coverage("--compare --world furnished --duration 300 --seeds 2 --plot " + plot);
  ASSERT_EQ(all.exit_code, 0) << all.output;
  EXPECT_NE(all.output.find("fsm              bt        coverage"), std::string::npos)
      << all.output;
  EXPECT_TRUE(std::ifstream(plot).good());
}

TEST(RoombaCoverage, a_robot_put_down_against_a_wall_has_not_bumped_and_cleans) {
  // The bottom wall of the lab's room touches the disc at y = 0.17 m (the robot's radius).
  const Outcome out = coverage("--behavior coverage --world empty --pose 3.2,0.17 --duration 400");
  ASSERT_EQ(out.exit_code, 0) << out.output;
  EXPECT_NE(out.output.find("bumps per run                        0"), std::string::npos)
      << out.output;
  EXPECT_GT(coverageAt(out.output, 300), 95.0) << out.output;
}

TEST(RoombaCoverage, a_pose_seen_late_bumps_unless_the_tree_drives_it_forward) {
  // Three steps late (what a loaded machine gives roomba_bt at 5x real time for a moment): the
  // robot acts on where it was and bumps at the rows' ends. Driving the pose forward along its
  // own commands (roomba_bt's ~pose_latency) cleans as if nothing were late.
  const std::string furnished = "--behavior coverage --world furnished --duration 300";
  const Outcome on_time = coverage(furnished);
  const Outcome late = coverage(furnished + " --lag 3 --predict 0");
  const Outcome predicted = coverage(furnished + " --lag 3");
  for (const Outcome* out : {&on_time, &late, &predicted})
    ASSERT_EQ(out->exit_code, 0) << out->output;
  const std::string no_bump = "bumps per run                        0";
  EXPECT_NE(on_time.output.find(no_bump), std::string::npos) << on_time.output;
  EXPECT_EQ(late.output.find(no_bump), std::string::npos) << late.output;
  EXPECT_NE(predicted.output.find(no_bump), std::string::npos) << predicted.output;
  EXPECT_EQ(coverageAt(predicted.output, 300), coverageAt(on_time.output, 300)) << predicted.output;

  const Outcome bad = coverage("--behavior coverage --lag 1.5");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--lag needs a whole number of steps"), std::string::npos)
      << bad.output;
}

}  // namespace
