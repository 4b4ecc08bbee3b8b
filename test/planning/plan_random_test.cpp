// The streams a plan draws from: the fast one is xoshiro256+ exactly and depends on its seed
// alone; the MATLAB one stays MATLAB's, bit for bit, whichever way it is reached.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <vector>

#include "planning_test_support.h"
#include "roomba_rrt/planning/plan_random.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::planning {
namespace {

using testing::labScenario;

std::vector<double> flat(const std::vector<Point2>& path) {
  std::vector<double> xy;
  for (const Point2& p : path) xy.insert(xy.end(), {p.x, p.y});
  return xy;
}

TEST(FastRandom, gives_xoshiro256plus_seeded_by_splitmix64) {
  // An independent implementation of Blackman and Vigna's reference code (state from four
  // SplitMix64 outputs of the seed) gives these first outputs.
  FastRandom zero(0);
  EXPECT_EQ(zero.next(), 0xdaac60e1ed6a4f9bu);
  EXPECT_EQ(zero.next(), 0x3156a1da0dc08435u);
  EXPECT_EQ(zero.next(), 0xf9ba3e3285d046abu);
  FastRandom seeded(42);
  EXPECT_DOUBLE_EQ(seeded.uniform(), 0.08575559529546095);  // 0x15f414253e365229 >> 11, / 2^53
  EXPECT_DOUBLE_EQ(seeded.uniform(), 0.31041139572710486);
}

TEST(FastRandom, the_same_seed_gives_the_same_stream_and_other_seeds_other_streams) {
  std::set<double> firsts;
  for (std::uint32_t seed : {0u, 1u, 2u, 42u, 43u, 4294967295u}) {
    FastRandom a(seed), b(seed);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.uniform(), b.uniform()) << "seed " << seed;
    firsts.insert(FastRandom(seed).uniform());
  }
  EXPECT_EQ(firsts.size(), 6u);
}

TEST(FastRandom, values_are_uniform_in_the_unit_interval) {
  FastRandom random(7);
  int below_half = 0, bins[10] = {};
  constexpr int kDraws = 100000;
  for (int i = 0; i < kDraws; ++i) {
    const double v = random.uniform();
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
    below_half += v < 0.5;
    ++bins[static_cast<int>(v * 10)];
  }
  EXPECT_NEAR(below_half, kDraws / 2, 500);  // about 3 standard deviations
  for (int count : bins) EXPECT_NEAR(count, kDraws / 10, 400);
  const double v = random.uniform(2.0, 3.0);
  EXPECT_GE(v, 2.0);
  EXPECT_LT(v, 3.0);
}

TEST(PlanRandom, the_matlab_stream_is_matlabs_owned_or_continued) {
  PlanRandom owned(42, RandomStream::kMatlab);
  MatlabRandom reference(42), continued_source(42);
  PlanRandom continued(continued_source);
  EXPECT_EQ(owned.stream(), RandomStream::kMatlab);
  for (int i = 0; i < 2000; ++i) {  // more than three MT19937 batches
    const double expected = reference.uniform();
    ASSERT_EQ(owned.uniform(), expected) << i;
    ASSERT_EQ(continued.uniform(), expected) << i;
  }
  PlanRandom fast(42, RandomStream::kFast);
  FastRandom fast_reference(42);
  EXPECT_EQ(fast.stream(), RandomStream::kFast);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(fast.uniform(), fast_reference.uniform());
}

TEST(PlanRandom, stream_names_parse_and_print) {
  EXPECT_EQ(parseRandomStream("matlab"), RandomStream::kMatlab);
  EXPECT_EQ(parseRandomStream("fast"), RandomStream::kFast);
  EXPECT_FALSE(parseRandomStream("mt19937"));
  EXPECT_EQ(toString(RandomStream::kFast), "fast");
  EXPECT_EQ(toString(RandomStream::kMatlab), "matlab");
}

TEST(PlanRandom, a_fast_plan_depends_on_its_seed_alone_and_is_not_the_labs) {
  const Problem room =
      world_planning::loadRoom(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  Problem query = room;
  query.start = {0.6, 2.0};
  query.goal = {4.4, 4.2};
  for (Algorithm algorithm : {Algorithm::kRrt, Algorithm::kRrtConnect, Algorithm::kRrtStar}) {
    PlannerOptions options;
    options.algorithm = algorithm;
    options.collision = CollisionCheck::kSegments;
    options.max_iterations = 5000;
    options.random_stream = RandomStream::kFast;
    std::set<std::vector<double>> paths;
    for (std::uint32_t seed : {1u, 2u, 3u}) {
      options.seed = seed;
      const PlanResult first = plan(query, options), again = plan(query, options);
      ASSERT_TRUE(first.success) << toString(algorithm) << " seed " << seed << ": "
                                 << first.message;
      EXPECT_EQ(flat(first.path), flat(again.path)) << toString(algorithm) << " seed " << seed;
      EXPECT_EQ(first.iterations, again.iterations);
      paths.insert(flat(first.path));
    }
    EXPECT_EQ(paths.size(), 3u) << toString(algorithm) << ": other seeds, other paths";
    options.seed = 1;
    const PlanResult fast = plan(query, options);
    options.random_stream = RandomStream::kMatlab;
    EXPECT_NE(flat(plan(query, options).path), flat(fast.path)) << toString(algorithm);
  }
}

TEST(PlanRandom, the_labs_scenarios_plan_as_before_by_default) {
  // The default stream is MATLAB's: the same answers as a plan continuing MatlabRandom(seed).
  for (const char* name : {"a", "d"}) {
    PlannerOptions options;
    options.seed = 7;
    MatlabRandom stream(7);
    const PlanResult by_default = plan(labScenario(name), options);
    const PlanResult continued = plan(labScenario(name), options, stream);
    EXPECT_EQ(flat(by_default.path), flat(continued.path)) << name;
    EXPECT_EQ(by_default.iterations, continued.iterations) << name;
  }
}

}  // namespace
}  // namespace roomba_rrt::planning
