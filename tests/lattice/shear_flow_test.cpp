// Simple shear: Couette flow between a resting and a moving bounce-back wall, and wall-free shear
// through the Lees-Edwards boundary. Both have a linear velocity profile, which the lattice
// Boltzmann equation with these boundaries reproduces exactly, so the bounds are set by how far
// the run is converged, not by the discretisation.
#include "flow_helpers.hpp"
#include "lattice/lees_edwards.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rbcsim::lattice {
namespace {

using testing::add_channel_walls;
using testing::relative_l2_error_x;

TEST(Couette, MovingWallGivesTheLinearProfile) {
  for (const char* collision : {"bgk", "trt"}) {
    const int width = 16;
    const double wall_speed = 0.02;
    FluidParameters parameters;
    parameters.collision = collision;
    parameters.collision_parameters.tau = 0.8;
    FluidSolver solver(LatticeGrid(4, width + 2, 1), parameters);
    add_channel_walls(solver, {wall_speed, 0.0, 0.0});
    ASSERT_TRUE(solver.run_to_steady_state({1e-9, 200, 200000}).converged);
    // Walls half-way at y = 1/2 (resting) and y = width + 1/2 (moving).
    const double error = relative_l2_error_x(
        solver, [&](int, int y, int) { return wall_speed * (y - 0.5) / width; });
    EXPECT_LT(error, 1e-6) << collision;
    for (std::size_t node = 0; node < solver.grid().node_count(); ++node) {
      if (solver.boundaries().is_fluid(node)) {
        EXPECT_NEAR(solver.velocity()[1][node], 0.0, 1e-12);
        EXPECT_NEAR(solver.density()[node], 1.0, 1e-9);
      }
    }
  }
}

TEST(LeesEdwards, SlidingImagesGiveTheLinearProfile) {
  const int height = 16;
  const double velocity_difference = 0.03;
  FluidParameters parameters;
  parameters.collision_parameters.tau = 0.8;
  parameters.lees_edwards_velocity = velocity_difference;
  FluidSolver solver(LatticeGrid(6, height, 2), parameters);
  ASSERT_TRUE(solver.run_to_steady_state({1e-9, 200, 200000}).converged);
  // Shear rate U / ny through the box and across the sliding planes; zero mean velocity.
  const double error = relative_l2_error_x(solver, [&](int, int y, int) {
    return velocity_difference / height * (y - 0.5 * (height - 1));
  });
  EXPECT_LT(error, 1e-6);
}

// With U = 0 the sliding boundary is plain periodicity: same result as no Lees-Edwards at all.
TEST(LeesEdwards, ZeroVelocityDifferenceIsPeriodic) {
  const auto shear_wave = [](std::optional<double> sliding) {
    FluidParameters parameters;
    parameters.lees_edwards_velocity = sliding;
    FluidSolver solver(LatticeGrid(5, 6, 3), parameters);
    const std::size_t n = solver.grid().node_count();
    VectorField velocity{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
    for (std::size_t node = 0; node < n; ++node) {
      const auto [x, y, z] = solver.grid().coordinates(node);
      velocity[0][node] = 0.03 * std::sin(0.9 * y + 0.4 * z);
      velocity[1][node] = 0.02 * std::cos(1.3 * x);
    }
    solver.initialise_equilibrium(std::vector<double>(n, 1.0), velocity);
    solver.advance(25);
    return solver.pre_collision_populations();
  };
  const auto sliding = shear_wave(0.0);
  const auto periodic = shear_wave(std::nullopt);
  for (std::size_t k = 0; k < sliding.size(); ++k) {
    ASSERT_NEAR(sliding[k], periodic[k], 1e-15);
  }
}

TEST(LeesEdwards, SourceIsInterpolatedFromTheDisplacedImage) {
  // Entering the bottom plane at x = 2 with c_x = 1 from an image displaced by 3.25: the
  // population left x - c_x + 3.25 = 4.25 of the top row.
  const auto bottom = lees_edwards_source(2, 1, 3.25, 8);
  EXPECT_EQ(bottom.x_low, 4);
  EXPECT_EQ(bottom.x_high, 5);
  EXPECT_DOUBLE_EQ(bottom.fraction, 0.25);
  // Entering the top plane at x = 0 with c_x = -1 from displacement -3.25: 1 - 3.25 = -2.25,
  // which wraps to 5.75 on a row of 8.
  const auto top = lees_edwards_source(0, -1, -3.25, 8);
  EXPECT_EQ(top.x_low, 5);
  EXPECT_EQ(top.x_high, 6);
  EXPECT_DOUBLE_EQ(top.fraction, 0.75);
  EXPECT_DOUBLE_EQ(lees_edwards_offset(0.3, 30, 8), 1.0);
  EXPECT_DOUBLE_EQ(lees_edwards_offset(-0.5, 3, 8), 6.5);
}

// The Galilean shift of the five populations that cross a plane together carries no mass, and
// adds dU times the mass that crosses, rho (1/6 + u_y/2), to their x-momentum.
TEST(LeesEdwards, GalileanShiftOfACrossingSetCarriesNoMass) {
  const double density = 1.02;
  const std::array<double, 3> velocity = {0.03, -0.01, 0.02};
  double mass = 0.0;
  double momentum_x = 0.0;
  for (int i = 0; i < kDirections; ++i) {
    if (kVelocities[i][1] == 1) {
      const double shift = galilean_shift(i, density, velocity, 0.05);
      mass += shift;
      momentum_x += shift * kVelocities[i][0];
    }
  }
  EXPECT_NEAR(mass, 0.0, 1e-16);
  EXPECT_NEAR(momentum_x, 0.05 * density * (1.0 / 6.0 + 0.5 * velocity[1]), 1e-16);
}

}  // namespace
}  // namespace rbcsim::lattice
