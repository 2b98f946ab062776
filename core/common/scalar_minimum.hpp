// Minimum of a function of one variable without derivatives, for fits whose every evaluation is a
// simulation (seconds each): few evaluations matter more than robustness to wild functions.
//
//   auto minimum = find_scalar_minimum(misfit, start, {.initial_step = 0.4, .tolerance = 1e-3});
//   if (!minimum.converged) ...  // e.g. still falling at the last point tried: no minimum
//
// Two stages: a downhill search from `start` that widens its steps by the golden ratio until the
// function rises again (a bracket a < b < c with f(b) below both ends), then Brent's method
// inside the bracket: parabolic interpolation through the three best points, with golden-section
// steps whenever the parabola is not trusted (R. P. Brent, Algorithms for Minimization without
// Derivatives, 1973, ch. 5). A function may return +infinity where it cannot be evaluated (a
// simulation that failed): such points only ever end a bracket, never enter a parabola.
#pragma once

#include <functional>

namespace rbcsim {

struct ScalarMinimumSettings {
  double initial_step = 0.4;  // first step of the downhill search, in x
  double tolerance = 1e-3;    // the minimum's x is known to within this (absolute)
  int max_evaluations = 40;   // both stages together
};

struct ScalarMinimum {
  double x = 0.0;
  double value = 0.0;
  int evaluations = 0;
  // false: the evaluations ran out before x was known to the tolerance: the function still fell
  // (or could not be evaluated on either side of `start`), or Brent's stage needed more. x is
  // then the lowest point seen, not necessarily a minimum.
  bool converged = false;
};

ScalarMinimum find_scalar_minimum(const std::function<double(double)>& function, double start,
                                  const ScalarMinimumSettings& settings);

}  // namespace rbcsim
