// Body-force-driven Poiseuille flow between half-way bounce-back walls and in a voxelised tube,
// against the analytic profiles (docs/validation.md, "Fluid solver").
#include "flow_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rbcsim::lattice {
namespace {

using testing::add_channel_walls;
using testing::relative_l2_error_x;

constexpr double kChannelPeakVelocity = 0.01;

// Converged to well below the discretisation errors measured here (1e-4 and less): the change
// per 200 steps is about a fifth of the remaining distance to steady state at the largest size.
SteadyStateCriterion tight_steady_state() { return {1e-9, 200, 400000}; }

// Plane channel of `width` fluid nodes, walls half-way at y = 1/2 and y = width + 1/2.
double plane_poiseuille_error(int width, const std::string& collision, double tau) {
  FluidParameters parameters;
  parameters.collision = collision;
  parameters.collision_parameters.tau = tau;
  const double viscosity = (tau - 0.5) / 3.0;
  const double force = 8.0 * viscosity * kChannelPeakVelocity / (width * width);
  parameters.body_force = {force, 0.0, 0.0};
  FluidSolver solver(LatticeGrid(4, width + 2, 1), parameters);
  add_channel_walls(solver);
  const auto steady = solver.run_to_steady_state(tight_steady_state());
  EXPECT_TRUE(steady.converged) << steady.relative_velocity_change;
  return relative_l2_error_x(solver, [&](int, int y, int) {
    return force / (2.0 * viscosity) * (y - 0.5) * (width + 0.5 - y);
  });
}

// BGK bounce-back misplaces the wall by a tau-dependent O(dx^2) amount (He et al., J. Stat. Phys.
// 87, 115 (1997)): the error is small and falls at second order.
TEST(PlanePoiseuille, BgkErrorBelowOnePercentAndSecondOrder) {
  const double coarse = plane_poiseuille_error(20, "bgk", 1.0);
  const double fine = plane_poiseuille_error(40, "bgk", 1.0);
  const double order = std::log2(coarse / fine);
  std::printf("plane Poiseuille BGK L2 error: 20 nodes %.3e, 40 nodes %.3e, order %.3f\n", coarse,
              fine, order);
  EXPECT_LT(coarse, 0.01);
  EXPECT_GT(order, 1.8);
}

// TRT with Lambda = 3/16 places half-way walls exactly: the parabola is the discrete solution.
TEST(PlanePoiseuille, TrtWithMagicParameterIsExact) {
  for (const double tau : {0.6, 1.0, 2.0}) {
    const double error = plane_poiseuille_error(20, "trt", tau);
    EXPECT_LT(error, 1e-6) << "tau " << tau;
  }
}

// Circular tube of `diameter` along x, axis between nodes: nodes whose centre lies within
// diameter/2 of the axis are fluid, the rest walls, so the wall is a staircase around the circle
// (it meets the circle half-way between nodes on the y and z axes).
double pipe_poiseuille_error(int diameter) {
  FluidParameters parameters;
  const double viscosity = (parameters.collision_parameters.tau - 0.5) / 3.0;
  const double radius = 0.5 * diameter;
  const double force = 4.0 * viscosity * kChannelPeakVelocity / (radius * radius);
  parameters.body_force = {force, 0.0, 0.0};
  const int width = diameter + 2;
  FluidSolver solver(LatticeGrid(1, width, width), parameters);  // x-invariant: one node long
  const double centre = 0.5 * (width - 1);
  const auto radial_squared = [&](int y, int z) {
    return (y - centre) * (y - centre) + (z - centre) * (z - centre);
  };
  for (std::size_t node = 0; node < solver.grid().node_count(); ++node) {
    const auto [x, y, z] = solver.grid().coordinates(node);
    if (radial_squared(y, z) >= radius * radius) {
      solver.set_wall(node);
    }
  }
  const auto steady = solver.run_to_steady_state(tight_steady_state());
  EXPECT_TRUE(steady.converged) << steady.relative_velocity_change;
  return relative_l2_error_x(solver, [&](int, int y, int z) {
    return force / (4.0 * viscosity) * (radius * radius - radial_squared(y, z));
  });
}

// Bounds for staircase walls. Half-way bounce-back on a voxelised circle is exact for the
// staircase, not for the circle: the wall wanders up to ~0.3 dx inside and outside the circle,
// and its hydraulic radius depends on how the lattice cuts the circle (the Gauss circle problem),
// which varies irregularly with the diameter. The L2 error therefore falls like dx^1 to dx^2 with
// scatter (measured with the axis between nodes: D = 10: 4.5 %, 16: 4.2 %, 20: 2.4 %, 24: 3.7 %,
// 30: 1.2 %, 40: 0.80 %). The 1 % target is met at 40 nodes across; at 20 nodes it needs
// curved-wall (interpolated) bounce-back, the "bouzidi" wall rule (curved_wall_test.cpp).
// Tested: under 3 % at 20 nodes, under 1 % at 40 nodes, and an observed order above 1.
TEST(PipePoiseuille, StaircaseErrorBoundedAndFallingWithResolution) {
  const double coarse = pipe_poiseuille_error(20);
  const double fine = pipe_poiseuille_error(40);
  const double order = std::log2(coarse / fine);
  std::printf("pipe Poiseuille L2 error: 20 nodes %.3e, 40 nodes %.3e, order %.3f\n", coarse, fine,
              order);
  EXPECT_LT(coarse, 0.03);
  EXPECT_LT(fine, 0.01);
  EXPECT_GT(order, 1.0);
}

}  // namespace
}  // namespace rbcsim::lattice
