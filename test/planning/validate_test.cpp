#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <functional>
#include <limits>

#include "planning_test_support.h"

namespace roomba_rrt::planning {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct BadInput {
  const char* what;
  std::function<void(Problem&, PlannerOptions&)> spoil;
  const char* field;  // the message must start with this
};

class RejectsBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(RejectsBadInput, with_a_message_naming_the_field_and_plans_nothing) {
  Problem problem = testing::labScenario("a");
  PlannerOptions options;
  GetParam().spoil(problem, options);
  const std::string error = testing::validationError(problem, options);
  EXPECT_EQ(error.rfind(GetParam().field, 0), 0u) << GetParam().what << ": '" << error << "'";
  const PlanResult r = plan(problem, options);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.tree.size(), 0);
  EXPECT_TRUE(std::isinf(r.length));
}

INSTANTIATE_TEST_SUITE_P(
    EveryField, RejectsBadInput,
    ::testing::Values(
        BadInput{"NaN start", [](Problem& p, PlannerOptions&) { p.start.x = kNaN; }, "start.x"},
        BadInput{"Inf goal", [](Problem& p, PlannerOptions&) { p.goal.y = kInf; }, "goal.y"},
        BadInput{"NaN bound", [](Problem& p, PlannerOptions&) { p.bounds.y_max = kNaN; },
                 "bounds.y_max"},
        BadInput{"NaN centre", [](Problem& p, PlannerOptions&) { p.obstacles[0].center.y = kNaN; },
                 "obstacles[0].center.y"},
        BadInput{"Inf radius", [](Problem& p, PlannerOptions&) { p.obstacles[0].radius = kInf; },
                 "obstacles[0].radius"},
        BadInput{"negative radius", [](Problem& p, PlannerOptions&) { p.obstacles[0].radius = -1; },
                 "obstacles[0].radius"},
        BadInput{"start outside",
                 [](Problem& p, PlannerOptions&) {
                   p.start = {-1, 1};
                 },
                 "start"},
        BadInput{"goal outside",
                 [](Problem& p, PlannerOptions&) {
                   p.goal = {9, 10.5};
                 },
                 "goal"},
        BadInput{"start in obstacle",
                 [](Problem& p, PlannerOptions&) {
                   p.start = {5, 5.5};
                 },
                 "start: inside obstacle 0"},
        BadInput{"goal in obstacle",
                 [](Problem& p, PlannerOptions&) {
                   p.goal = {4.5, 5};
                 },
                 "goal: inside obstacle 0"},
        BadInput{"empty bounds", [](Problem& p, PlannerOptions&) { p.bounds.x_max = 0; }, "bounds"},
        BadInput{"inverted bounds",
                 [](Problem& p, PlannerOptions&) { std::swap(p.bounds.y_min, p.bounds.y_max); },
                 "bounds"},
        BadInput{"span beyond double range",
                 [](Problem& p, PlannerOptions&) {
                   p.bounds.x_min = -1e308;
                   p.bounds.x_max = 1e308;
                 },
                 "bounds"},
        BadInput{"zero step", [](Problem&, PlannerOptions& o) { o.step = 0; }, "step"},
        BadInput{"negative step", [](Problem&, PlannerOptions& o) { o.step = -0.2; }, "step"},
        BadInput{"NaN step", [](Problem&, PlannerOptions& o) { o.step = kNaN; }, "step"},
        BadInput{"bias below 0", [](Problem&, PlannerOptions& o) { o.goal_bias = -0.1; },
                 "goal_bias"},
        BadInput{"bias above 1", [](Problem&, PlannerOptions& o) { o.goal_bias = 1.5; },
                 "goal_bias"},
        BadInput{"NaN bias", [](Problem&, PlannerOptions& o) { o.goal_bias = kNaN; }, "goal_bias"},
        BadInput{"no iterations", [](Problem&, PlannerOptions& o) { o.max_iterations = 0; },
                 "max_iterations"},
        BadInput{
            "iterations above the cap",
            [](Problem&, PlannerOptions& o) { o.max_iterations = kDefaultMaxIterationsCap + 1; },
            "max_iterations"},
        BadInput{"negative tolerance",
                 [](Problem&, PlannerOptions& o) { o.goal_tolerance = -1e-3; }, "goal_tolerance"},
        BadInput{"Inf tolerance", [](Problem&, PlannerOptions& o) { o.goal_tolerance = kInf; },
                 "goal_tolerance"},
        BadInput{"no rejection tries",
                 [](Problem&, PlannerOptions& o) { o.max_rejection_tries = 0; },
                 "max_rejection_tries"}),
    [](const ::testing::TestParamInfo<BadInput>& info) {
      std::string name = info.param.what;
      for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

TEST(Validate, accepts_the_lab_scenarios_with_the_lab_defaults) {
  for (const char* name : {"a", "b", "c", "d"}) {
    EXPECT_EQ(testing::validationError(testing::labScenario(name), PlannerOptions{}), "") << name;
  }
}

TEST(Validate, the_cap_is_inclusive) {
  PlannerOptions options;
  options.max_iterations = 100000;
  EXPECT_EQ(testing::validationError(testing::labScenario("a"), options, 100000), "");
}

TEST(Validate, throws_invalid_input_that_holds_the_field_path_and_the_problem_apart) {
  Problem problem = testing::labScenario("a");
  problem.rectangles = {{6, 1, 7, 2}, {3, 7, 2, 8}};
  try {
    validate(problem, PlannerOptions{});
    FAIL() << "accepted an inverted rectangle";
  } catch (const util::InvalidInput& invalid) {
    EXPECT_EQ(invalid.field(), "rectangles[1].max_x");
    EXPECT_EQ(invalid.problem(), "must be > min_x, got 2 <= 3 (an empty or inverted rectangle)");
    EXPECT_STREQ(invalid.what(),
                 "rectangles[1].max_x: must be > min_x, got 2 <= 3 (an empty or "
                 "inverted rectangle)");
  }
}

TEST(Validate, a_value_just_outside_a_range_is_printed_with_the_digits_that_show_why) {
  Problem problem = testing::labScenario("a");
  problem.bounds.y_max = 1000000.0000000012;  // 1e6 to six digits, but above it
  EXPECT_EQ(testing::validationError(problem, PlannerOptions{}),
            "bounds.y_max: must be in [-1e+06, 1e+06] m, got 1000000.0000000012");
  problem.bounds.y_max = 2e6;  // a round value stays as short as it was written
  EXPECT_EQ(testing::validationError(problem, PlannerOptions{}),
            "bounds.y_max: must be in [-1e+06, 1e+06] m, got 2e+06");
}

}  // namespace
}  // namespace roomba_rrt::planning
