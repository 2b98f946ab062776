// The wall time a run has left, extrapolated from its progress so far.
#include "common/wall_clock.hpp"

#include <gtest/gtest.h>

namespace {

using rbcsim::ProgressPoint;
using rbcsim::wall_time_left_s;

TEST(WallTimeLeft, ExtrapolatesTheRateSinceTheFirstPoint) {
  // 0.01 s of simulated time in 300 wall seconds from t = 0.002 s: 30 000 s per simulated second,
  // so 0.148 s more of a 0.16 s run takes 4440 s.
  const auto left = wall_time_left_s({0.002, 60.0}, {0.012, 360.0}, 0.16);
  ASSERT_TRUE(left.has_value());
  EXPECT_NEAR(*left, 4440.0, 1e-9);
}

TEST(WallTimeLeft, NothingBeforeTheRunHasMovedAndZeroPastItsEnd) {
  EXPECT_FALSE(wall_time_left_s({0.002, 60.0}, {0.002, 90.0}, 0.16).has_value());
  EXPECT_EQ(wall_time_left_s({0.0, 0.0}, {0.2, 100.0}, 0.16), 0.0);
}

}  // namespace
