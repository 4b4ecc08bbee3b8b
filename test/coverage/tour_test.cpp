// The touch-up's tour (tour.h): every visit once, from its nearer end, and no crossing left that
// nearest first makes.
#include "roomba_rrt/coverage/tour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace roomba_rrt::coverage {
namespace {

/// A stop: a visit of no length at p.
Polyline stop(double x, double y) { return {{x, y}, {x, y}}; }

/// Every visit exactly once.
void expectEachOnce(const std::vector<TourStop>& tour, std::size_t visits) {
  ASSERT_EQ(tour.size(), visits);
  std::vector<int> seen(visits, 0);
  for (const TourStop& s : tour) ++seen.at(s.visit);
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(visits));
}

TEST(TouchUpTour, a_row_is_driven_from_its_nearer_end) {
  // Up the first row, then the second, which was given the other way round.
  const std::vector<Polyline> visits{{{0, 1}, {0, 5}}, {{1, 1}, {1, 5}}};
  const std::vector<TourStop> tour = touchUpTour(visits, {0, 0});
  expectEachOnce(tour, visits.size());
  EXPECT_EQ(tour[0].visit, 0u);
  EXPECT_FALSE(tour[0].reversed);
  EXPECT_EQ(tour[1].visit, 1u);
  EXPECT_TRUE(tour[1].reversed);
  EXPECT_DOUBLE_EQ(tourJumps(visits, tour, {0, 0}), 2.0);
}

TEST(TouchUpTour, the_spot_nearest_first_leaves_for_last_is_taken_on_the_way) {
  // From (0, 0) nearest first goes (-2, 1), (-2, -1), (1, -2), and then back across to (-4, 2):
  // 13.8 m of jumps. The shortest tour takes (1, -2) first and ends at (-4, 2): 9.6 m.
  const std::vector<Polyline> visits{stop(-4, 2), stop(-2, 1), stop(1, -2), stop(-2, -1)};
  const std::vector<TourStop> tour = touchUpTour(visits, {0, 0});
  expectEachOnce(tour, visits.size());
  EXPECT_NEAR(tourJumps(visits, tour, {0, 0}), 9.634, 1e-3);
  EXPECT_EQ(tour.front().visit, 2u);
  EXPECT_EQ(tour.back().visit, 0u);
}

TEST(TouchUpTour, no_reversal_of_a_stretch_shortens_the_tour_it_returns) {
  // 60 spots and rows, placed by a fixed linear congruential generator (the same everywhere).
  std::uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24) * 10;  // [0, 10) m
  };
  std::vector<Polyline> visits;
  for (int k = 0; k < 60; ++k) {
    const double x = next(), y = next();
    visits.push_back(k % 3 ? stop(x, y) : Polyline{{x, y}, {x, y + 1}});
  }
  const Point2 start{5, 5};
  const std::vector<TourStop> tour = touchUpTour(visits, start);
  expectEachOnce(tour, visits.size());
  const double jumps = tourJumps(visits, tour, start);
  for (std::size_t i = 0; i < tour.size(); ++i) {
    for (std::size_t j = i + 1; j < tour.size(); ++j) {
      std::vector<TourStop> other = tour;
      std::reverse(other.begin() + static_cast<std::ptrdiff_t>(i),
                   other.begin() + static_cast<std::ptrdiff_t>(j) + 1);
      for (std::size_t k = i; k <= j; ++k) other[k].reversed = !other[k].reversed;
      ASSERT_GE(tourJumps(visits, other, start), jumps - 1e-6) << i << ".." << j;
    }
  }
}

TEST(TouchUpTour, nothing_to_visit_is_an_empty_tour) {
  EXPECT_TRUE(touchUpTour({}, {0, 0}).empty());
}

}  // namespace
}  // namespace roomba_rrt::coverage
