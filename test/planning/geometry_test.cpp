#include <gtest/gtest.h>

#include "../common/hostile_yaml.h"

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/lab/matlab_random.h"
#include "roomba_rrt/planning/lab/scenarios.h"
#include "roomba_rrt/planning/planner_options.h"

namespace roomba_rrt::planning {
namespace {

const Circle kUnitAtOrigin{{0, 0}, 1};

TEST(Geometry, segment_passing_through_a_circle_meets_it_even_with_both_ends_outside) {
  EXPECT_TRUE(segmentMeets({{-2, 0.5}, {2, 0.5}}, kUnitAtOrigin));
}

TEST(Geometry, segment_passing_beside_a_circle_does_not_meet_it) {
  EXPECT_FALSE(segmentMeets({{-2, 1.01}, {2, 1.01}}, kUnitAtOrigin));
  // The infinite line crosses the circle, the segment stops before it.
  EXPECT_FALSE(segmentMeets({{-3, 0}, {-1.01, 0}}, kUnitAtOrigin));
}

TEST(Geometry, touching_the_rim_counts_as_a_collision) {
  EXPECT_TRUE(segmentMeets({{-2, 1}, {2, 1}}, kUnitAtOrigin));
  EXPECT_TRUE(contains(kUnitAtOrigin, Point2{1, 0}));
}

TEST(Geometry, zero_length_segment_is_a_point_test) {
  EXPECT_TRUE(segmentMeets({{0.5, 0}, {0.5, 0}}, kUnitAtOrigin));
  EXPECT_FALSE(segmentMeets({{1.5, 0}, {1.5, 0}}, kUnitAtOrigin));
}

TEST(PlannerOptions, names_round_trip_and_unknown_names_are_rejected) {
  for (auto a : {Algorithm::kRrt, Algorithm::kRrtConnect, Algorithm::kRrtStar}) {
    EXPECT_EQ(parseAlgorithm(toString(a)), a);
  }
  for (auto c : {CollisionCheck::kPoints, CollisionCheck::kSegments}) {
    EXPECT_EQ(parseCollisionCheck(toString(c)), c);
  }
  EXPECT_EQ(toString(Algorithm::kRrtConnect), "rrt_connect");
  EXPECT_EQ(toString(CollisionCheck::kSegments), "segments");
  EXPECT_FALSE(parseAlgorithm("prm"));
  EXPECT_FALSE(parseCollisionCheck("edges"));
  EXPECT_FALSE(parseNearestSearch("kdtree"));
}

TEST(Scenarios, the_lab_file_holds_the_four_scenarios_of_the_lab) {
  const auto s = loadScenarios(ROOMBA_RRT_CONFIG_DIR "/rrt_scenarios.yaml");
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s.at("a").obstacles.size(), 1u);
  EXPECT_EQ(s.at("b").obstacles.size(), 3u);
  EXPECT_EQ(s.at("c").obstacles.size(), 4u);
  ASSERT_EQ(s.at("d").obstacles.size(), 5u);
  EXPECT_DOUBLE_EQ(s.at("d").obstacles[0].radius, 0.8);
  EXPECT_DOUBLE_EQ(s.at("d").start.x, 9);
  EXPECT_DOUBLE_EQ(s.at("d").goal.y, 1);
  EXPECT_DOUBLE_EQ(s.at("a").bounds.x_max, 10);
}

TEST(Scenarios, a_malformed_file_is_an_error_naming_the_field) {
  const std::string path = ::testing::TempDir() + "bad_scenarios.yaml";
  FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("scenarios:\n  x:\n    start: [1]\n    goal: [2, 2]\n", f);
  std::fclose(f);
  try {
    loadScenarios(path);
    FAIL() << "expected an error";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(e.field(), "scenarios.x.start");
    EXPECT_EQ(std::string(e.what()), path + ": scenarios.x.start: expected [x, y]");
  }
  EXPECT_THROW(loadScenarios("/nonexistent/scenarios.yaml"), util::InvalidInput);
  f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("scenarios:\n  x: {start: [1, 1], goal: [2, 2]}\n  x: {start: [1, 1]}\n", f);
  std::fclose(f);
  try {
    loadScenarios(path);
    FAIL() << "a scenario given twice was read";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), path +
                                         ": scenarios.x: is given twice (lines 2 and 3); a "
                                         "mapping holds one value per key");
  }
  // Issue 44: an alias bomb is refused at its first anchor.
  f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(
      ("scenarios:\n  x: {start: [1, 1], goal: [2, 2]}\n" + roomba_rrt::test::aliasBomb(9)).c_str(),
      f);
  std::fclose(f);
  try {
    loadScenarios(path);
    FAIL() << "an alias bomb was read";
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), path + ": " + roomba_rrt::test::aliasRefusal(3, 5));
  }
}

TEST(Geometry, checker_quick_test_gives_the_exact_test_answer_for_segments_grazing_a_disc) {
  // Short segments whose far end lies within 1e-9 of the rim, from every side: the checker's
  // quick distance test must never disagree with the exact segment-circle test.
  const Circle disc{{5, 5}, 1.05};
  const CollisionChecker checker({disc}, CollisionCheck::kSegments);
  MatlabRandom random(3);
  for (int i = 0; i < 100000; ++i) {
    const double angle = random.uniform(0, 2 * M_PI);
    const double rim = disc.radius + random.uniform(-1e-9, 1e-9);
    const Point2 b{disc.center.x + rim * std::cos(angle), disc.center.y + rim * std::sin(angle)};
    // Half of them straight out from the centre: then a is at r + length, the quick test's edge.
    const double away = i % 2 == 0 ? angle : random.uniform(0, 2 * M_PI);
    const double length = random.uniform(0, 0.2);
    const Point2 a{b.x + length * std::cos(away), b.y + length * std::sin(away)};
    ASSERT_EQ(checker.isSegmentFree(a, b), !segmentMeets({a, b}, disc)) << "segment " << i;
  }
}

}  // namespace
}  // namespace roomba_rrt::planning
