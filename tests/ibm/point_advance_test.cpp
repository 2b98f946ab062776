// Moving massless points: forward Euler, and second-order Adams-Bashforth checked against exact
// solutions (exact for a velocity linear in time; observed order on dx/dt = -x).
#include "ibm/point_advance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "ibm/expect_input_error.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::ibm::find_point_advance_scheme;
using rbcsim::ibm::PointAdvancer;

TEST(AdvancePoints, ForwardEulerMovesByVelocityTimesStep) {
  std::vector<Vec3> positions{Vec3(1, 2, 3), Vec3(-0.5, 0.25, 8)};
  const std::vector<Vec3> velocities{Vec3(0.01, -0.02, 0.03), Vec3(0, 0.5, -0.25)};
  rbcsim::ibm::advance_points(positions, velocities, 2.0);
  EXPECT_EQ(positions[0], Vec3(1.02, 1.96, 3.06));
  EXPECT_EQ(positions[1], Vec3(-0.5, 1.25, 7.5));
  rbcsim::ibm::advance_points(positions, velocities);  // dt = 1 by default (lattice units)
  EXPECT_EQ(positions[1], Vec3(-0.5, 1.75, 7.25));
}

TEST(PointAdvanceSchemes, RegistryFindsEachSchemeByNameAndRejectsUnknownOnes) {
  EXPECT_EQ(find_point_advance_scheme("euler").order, 1);
  EXPECT_EQ(find_point_advance_scheme("ab2").order, 2);
  for (const auto& scheme : rbcsim::ibm::point_advance_schemes()) {
    EXPECT_EQ(&find_point_advance_scheme(scheme.name), &scheme);
  }
  expect_input_error_mentioning([] { find_point_advance_scheme("rk4"); },
                                {"ibm.point_advance", "rk4", "euler, ab2"});
}

// u(t) = a + b t. After the first (Euler) step, which misses b dt^2 / 2, AB2 integrates a velocity
// linear in time exactly, also when the step changes.
TEST(PointAdvancer, AdamsBashforth2IsExactForVelocityLinearInTime) {
  const Vec3 a(0.1, -0.2, 0.05), b(0.03, 0.01, -0.02), start(1, 2, 3);
  PointAdvancer advancer(find_point_advance_scheme("ab2"));
  std::vector<Vec3> position{start};
  double time = 0.0;
  const double first_dt = 0.1;
  for (const double dt : {first_dt, 0.1, 0.2, 0.05, 0.3}) {
    const std::vector<Vec3> velocity{a + b * time};
    advancer.advance(position, velocity, dt);
    time += dt;
    const Vec3 exact = start + a * time + 0.5 * b * time * time;
    const Vec3 first_step_error = -0.5 * b * first_dt * first_dt;
    EXPECT_LT((position[0] - (exact + first_step_error)).norm(), 1e-15) << "t = " << time;
  }
}

// Global error at t = 1 of dx/dt = -x, x(0) = 1, with the velocity taken at the current position.
double decay_error(const std::string& scheme, int steps) {
  PointAdvancer advancer(find_point_advance_scheme(scheme));
  std::vector<Vec3> position{Vec3(1, 1, 1)};
  const double dt = 1.0 / steps;
  for (int step = 0; step < steps; ++step) {
    const std::vector<Vec3> velocity{-position[0]};
    advancer.advance(position, velocity, dt);
  }
  return std::abs(position[0].x() - std::exp(-1.0));
}

TEST(PointAdvancer, ObservedOrdersAreOneForEulerAndTwoForAdamsBashforth2) {
  for (const auto& [scheme, order] : {std::pair{"euler", 1.0}, std::pair{"ab2", 2.0}}) {
    const double observed = std::log2(decay_error(scheme, 40) / decay_error(scheme, 80));
    EXPECT_NEAR(observed, order, 0.1) << scheme;
  }
}

TEST(PointAdvancer, AChangeInThePointCountNeedsForgettingTheHistory) {
  PointAdvancer advancer(find_point_advance_scheme("ab2"));
  std::vector<Vec3> two{Vec3::Zero(), Vec3::Zero()}, three(3, Vec3::Zero());
  const std::vector<Vec3> two_velocities(2, Vec3::Ones()), three_velocities(3, Vec3::Ones());
  advancer.advance(two, two_velocities);
  EXPECT_THROW(advancer.advance(three, three_velocities), std::invalid_argument);
  EXPECT_THROW(advancer.advance(two, three_velocities), std::invalid_argument);
  advancer.forget_history();
  advancer.advance(three, three_velocities);
  EXPECT_EQ(three[0], Vec3::Ones());  // a first step again: Euler
}

}  // namespace
