// The shared geometry against brute force: dense samples of segments and of the shapes' borders,
// near circles and rectangles, with and without a margin (the grown shapes the planner uses).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::geometry {
namespace {

constexpr int kSegmentSamples = 150;
constexpr int kBorderSamples = 150;  // per side of a rectangle, or around a circle

std::vector<Point2> sampleSegment(const Segment& s) {
  std::vector<Point2> points;
  for (int i = 0; i <= kSegmentSamples; ++i) {
    const double t = static_cast<double>(i) / kSegmentSamples;
    points.push_back({s.a.x + t * (s.b.x - s.a.x), s.a.y + t * (s.b.y - s.a.y)});
  }
  return points;
}

std::vector<Point2> sampleBorder(const Rectangle& r) {
  std::vector<Point2> points;
  for (int i = 0; i <= kBorderSamples; ++i) {
    const double t = static_cast<double>(i) / kBorderSamples;
    const double x = r.min_x + t * (r.max_x - r.min_x), y = r.min_y + t * (r.max_y - r.min_y);
    points.insert(points.end(), {{x, r.min_y}, {x, r.max_y}, {r.min_x, y}, {r.max_x, y}});
  }
  return points;
}

std::vector<Point2> sampleBorder(const Circle& c) {
  std::vector<Point2> points;
  for (int i = 0; i < 4 * kBorderSamples; ++i) {
    const double a = 2 * M_PI * i / (4 * kBorderSamples);
    points.push_back({c.center.x + c.radius * std::cos(a), c.center.y + c.radius * std::sin(a)});
  }
  return points;
}

bool insideBrute(const Rectangle& r, const Point2& p) {
  return r.min_x <= p.x && p.x <= r.max_x && r.min_y <= p.y && p.y <= r.max_y;
}
bool insideBrute(const Circle& c, const Point2& p) {
  return std::hypot(p.x - c.center.x, p.y - c.center.y) <= c.radius;
}

/// The smallest distance between sample points of the segment and of the shape (0 when a sample
/// of the segment is inside the shape). Never below the true distance; above it by at most the
/// sampling's spacing.
template <typename Shape>
double bruteDistance(const Shape& shape, const Segment& s) {
  const std::vector<Point2> border = sampleBorder(shape);
  double best = INFINITY;
  for (const Point2& p : sampleSegment(s)) {
    if (insideBrute(shape, p)) return 0;
    for (const Point2& q : border) best = std::min(best, std::hypot(p.x - q.x, p.y - q.y));
  }
  return best;
}

// Random shapes near the origin and segments of up to a few metres around them.
struct Cases {
  std::mt19937 rng{20240611};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng); }
  Rectangle rectangle() {
    const double x = uniform(-1, 0.5), y = uniform(-1, 0.5);
    return {x, y, x + uniform(0.05, 1.5), y + uniform(0.05, 1.5)};
  }
  Circle circle() { return {{uniform(-0.5, 0.5), uniform(-0.5, 0.5)}, uniform(0.05, 1.0)}; }
  Segment segment() {
    const Point2 a{uniform(-2, 2), uniform(-2, 2)};
    if (uniform(0, 1) < 0.1) return {a, a};  // a point
    return {a, {a.x + uniform(-2, 2), a.y + uniform(-2, 2)}};
  }
};

// The brute force is this far above the truth at most (border and segment spacing).
constexpr double kSampling = 0.02;

/// Checks segmentMeets(s, shape, margin) against the brute-force distance for 300 random cases of
/// `make_shape` and margins 0, 0.17 (the Roomba) and 0.5; `also` adds checks per case.
template <typename MakeShape, typename Also>
void expectSegmentTestsMatchBruteForce(Cases& cases, MakeShape make_shape, Also also) {
  int met = 0, missed = 0;
  for (int i = 0; i < 300; ++i) {
    const auto shape = make_shape();
    const Segment s = cases.segment();
    const double brute = bruteDistance(shape, s);
    also(shape, s, brute, i);
    for (const double margin : {0.0, 0.17, 0.5}) {
      if (std::abs(brute - margin) <= kSampling) continue;  // too close to call by sampling
      const bool meets = segmentMeets(s, shape, margin);
      ASSERT_EQ(meets, brute < margin || (margin == 0 && brute == 0)) << "case " << i;
      (meets ? met : missed)++;
    }
  }
  EXPECT_GT(met, 100);  // both answers are exercised
  EXPECT_GT(missed, 100);
}

TEST(Geometry, segment_rectangle_distance_and_tests_match_brute_force_grown_and_not) {
  Cases cases;
  expectSegmentTestsMatchBruteForce(
      cases, [&] { return cases.rectangle(); },
      [](const Rectangle& box, const Segment& s, double brute, int i) {
        const double exact = distance(box, s);
        ASSERT_LE(exact, brute + 1e-12) << "case " << i;
        ASSERT_GE(exact, brute - kSampling) << "case " << i;
        ASSERT_EQ(segmentIntersects(s, box), exact == 0) << "case " << i;
      });
}

TEST(Geometry, segment_circle_test_matches_brute_force_grown_and_not) {
  Cases cases;
  expectSegmentTestsMatchBruteForce(
      cases, [&] { return cases.circle(); }, [](const Circle&, const Segment&, double, int) {});
}

TEST(Geometry, point_tests_match_brute_force_near_shapes) {
  Cases cases;
  for (int i = 0; i < 500; ++i) {
    const Rectangle box = cases.rectangle();
    const Circle c = cases.circle();
    const Point2 p{cases.uniform(-2, 2), cases.uniform(-2, 2)};
    ASSERT_EQ(contains(box, p), insideBrute(box, p));
    ASSERT_EQ(contains(c, p), insideBrute(c, p));
    const double brute = bruteDistance(box, Segment{p, p});
    ASSERT_NEAR(distance(box, p), brute, kSampling) << "case " << i;
    const Point2 q = closestPoint(box, p);
    ASSERT_TRUE(insideBrute(box, q));
    ASSERT_NEAR(std::hypot(p.x - q.x, p.y - q.y), distance(box, p), 1e-12);
    for (const double margin : {0.0, 0.17}) {
      if (std::abs(brute - margin) > kSampling) {
        ASSERT_EQ(withinMargin(box, p, margin), brute <= margin) << "case " << i;
      }
    }
  }
}

TEST(Geometry, grown_rectangle_is_round_at_the_corners_not_a_bounding_box) {
  const Rectangle unit{0, 0, 1, 1};
  // (1.15, 1.15) is inside the 0.2-grown bounding box but 0.212 from the corner.
  EXPECT_FALSE(withinMargin(unit, {1.15, 1.15}, 0.2));
  EXPECT_TRUE(withinMargin(unit, {1.14, 1.14}, 0.2));
  // A segment passing the corner diagonally at 0.21 misses it; at 0.19 it meets it.
  const double off = 0.21 / std::sqrt(2.0);
  EXPECT_FALSE(segmentMeets({{1 + off - 1, 1 + off + 1}, {1 + off + 1, 1 + off - 1}}, unit, 0.2));
  const double near = 0.19 / std::sqrt(2.0);
  EXPECT_TRUE(
      segmentMeets({{1 + near - 1, 1 + near + 1}, {1 + near + 1, 1 + near - 1}}, unit, 0.2));
}

TEST(Geometry, segment_inside_a_rectangle_or_along_its_edge_meets_it) {
  const Rectangle box{0, 0, 2, 1};
  EXPECT_TRUE(segmentMeets({{0.5, 0.5}, {1.5, 0.5}}, box));  // wholly inside
  EXPECT_TRUE(segmentMeets({{-1, 1}, {3, 1}}, box));         // along the top edge
  EXPECT_FALSE(segmentMeets({{-1, 1.001}, {3, 1.001}}, box));
  EXPECT_DOUBLE_EQ(distance(box, Segment{{-1, 2}, {3, 2}}), 1.0);
}

TEST(Geometry, path_length_is_the_sum_of_its_segments) {
  EXPECT_DOUBLE_EQ(pathLength({{0, 0}, {3, 4}, {3, 5}}), 6.0);
  EXPECT_DOUBLE_EQ(pathLength({{1, 1}}), 0.0);
}

}  // namespace
}  // namespace roomba_rrt::geometry
