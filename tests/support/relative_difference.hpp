// |value - expected| / |expected|: the measure of the percentage tolerances in the tests.
#pragma once

#include <cmath>

namespace rbcsim::testing {

inline double relative_difference(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

}  // namespace rbcsim::testing
