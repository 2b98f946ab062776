// The one-dimensional minimiser behind the calibrate fits that run simulations: minima known in
// closed form, found within the tolerance, in few evaluations, across regions where the function
// cannot be evaluated; and an honest "not converged" when there is no minimum.
#include "common/scalar_minimum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace {

using rbcsim::find_scalar_minimum;
using rbcsim::ScalarMinimumSettings;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
const ScalarMinimumSettings kSettings{
    .initial_step = 0.4, .tolerance = 1e-4, .max_evaluations = 40};

// Parabolic interpolation is exact on a parabola: a handful of evaluations after the bracket.
TEST(ScalarMinimum, FindsTheVertexOfAParabolaInFewEvaluations) {
  const auto minimum =
      find_scalar_minimum([](double x) { return (x - 2.0) * (x - 2.0) + 1.0; }, 0.0, kSettings);
  EXPECT_TRUE(minimum.converged);
  EXPECT_NEAR(minimum.x, 2.0, 1e-4);
  EXPECT_NEAR(minimum.value, 1.0, 1e-8);
  EXPECT_LE(minimum.evaluations, 12);
}

// Skewed and searched downhill to the left of the start: e^x - 3x has its minimum at ln 3.
TEST(ScalarMinimum, FindsAnAsymmetricMinimumDownhillOfTheStart) {
  const auto minimum =
      find_scalar_minimum([](double x) { return std::exp(x) - 3.0 * x; }, 5.0, kSettings);
  EXPECT_TRUE(minimum.converged);
  EXPECT_NEAR(minimum.x, std::log(3.0), 1e-4);
  EXPECT_LE(minimum.evaluations, 25);
}

// A fit's simulation fails for some parameters (+infinity): such points bound the search and
// never enter a parabola. The minimum is 0.05 from where the function stops being defined.
TEST(ScalarMinimum, SkipsPointsThatCannotBeEvaluated) {
  const auto function = [](double x) {
    return x < 0.65 ? kInfinity : std::pow(x - 0.7, 2) + std::pow(x - 0.7, 4);
  };
  for (const double start : {0.66, 3.0}) {
    const auto minimum = find_scalar_minimum(function, start, kSettings);
    EXPECT_TRUE(minimum.converged) << start;
    EXPECT_NEAR(minimum.x, 0.7, 1e-4) << start;
  }
}

// A function that falls for ever has no minimum: not converged, at the lowest point tried, with
// the evaluations spent.
TEST(ScalarMinimum, ReportsAFunctionWithoutMinimumAsNotConverged) {
  const auto falling = find_scalar_minimum([](double x) { return -x; }, 0.0, kSettings);
  EXPECT_FALSE(falling.converged);
  EXPECT_EQ(falling.evaluations, kSettings.max_evaluations);
  EXPECT_GT(falling.x, 100.0);
  EXPECT_EQ(falling.value, -falling.x);

  const auto undefined = find_scalar_minimum([](double) { return kInfinity; }, 1.0, kSettings);
  EXPECT_FALSE(undefined.converged);
  EXPECT_EQ(undefined.evaluations, 2);
}

// The tolerance is what the caller asked for, not a fixed one: a coarser one stops earlier.
TEST(ScalarMinimum, CoarserToleranceTakesFewerEvaluations) {
  const auto function = [](double x) { return std::cosh(x - std::numbers::pi); };
  auto coarse_settings = kSettings;
  coarse_settings.tolerance = 1e-2;
  const auto fine = find_scalar_minimum(function, 0.0, kSettings);
  const auto coarse = find_scalar_minimum(function, 0.0, coarse_settings);
  EXPECT_NEAR(fine.x, std::numbers::pi, 1e-4);
  EXPECT_NEAR(coarse.x, std::numbers::pi, 1e-2);
  EXPECT_LT(coarse.evaluations, fine.evaluations);
}

}  // namespace
