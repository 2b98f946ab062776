// Channel flow driven by a velocity inlet with a Poiseuille profile and a pressure outlet: the
// profile is carried through unchanged, the flux is the imposed one, and the pressure falls
// linearly at the Poiseuille rate dp/dx = -12 rho nu U_mean / H^2.
#include "flow_helpers.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rbcsim::lattice {
namespace {

using testing::add_channel_walls;

TEST(InletOutlet, PoiseuilleInflowReachesThePressureOutlet) {
  const int height = 16;
  const int length = 32;
  const double mean_velocity = 0.005;
  FluidParameters parameters;
  parameters.collision_parameters.tau = 0.8;
  FluidSolver solver(LatticeGrid(length, height + 2, 1), parameters);
  const LatticeGrid& grid = solver.grid();
  // Half-way walls at y = 1/2 and y = height + 1/2.
  const auto profile = [&](int y) {
    return 6.0 * mean_velocity * (y - 0.5) * (height + 0.5 - y) / (height * height);
  };
  add_channel_walls(solver);
  for (int y = 1; y <= height; ++y) {
    solver.set_velocity_inlet(grid.index(0, y, 0), {profile(y), 0.0, 0.0});
    solver.set_pressure_outlet(grid.index(length - 1, y, 0), 1.0);
  }
  const auto steady = solver.run_to_steady_state({1e-8, 200, 200000});
  ASSERT_TRUE(steady.converged) << steady.relative_velocity_change;

  // The central half of the channel. Within a few nodes of the ends the profile is perturbed: the
  // outlet rule takes the velocity of its neighbouring node as the wall velocity. Elsewhere the
  // weakly compressible fluid (density falls by ~2e-3 along the channel, so u = flux / rho rises
  // by as much) reproduces the parabola to a few 1e-3; the bounds leave room for that.
  const int first = length / 4;
  const int last = 3 * length / 4;
  double error_squared = 0.0;
  double norm_squared = 0.0;
  for (int x = first; x <= last; ++x) {
    double flux = 0.0;
    for (int y = 1; y <= height; ++y) {
      const std::size_t node = grid.index(x, y, 0);
      const double difference = solver.velocity()[0][node] - profile(y);
      error_squared += difference * difference;
      norm_squared += profile(y) * profile(y);
      flux += solver.density()[node] * solver.velocity()[0][node];
    }
    EXPECT_NEAR(flux / (mean_velocity * height), 1.0, 0.01) << "x = " << x;
  }
  const double profile_error = std::sqrt(error_squared / norm_squared);
  std::printf("inlet/outlet: L2 error of the central profile %.3e\n", profile_error);
  EXPECT_LT(profile_error, 0.01);

  // Pressure gradient along the centre line, p = rho c_s^2.
  const int centre = height / 2;
  const double pressure_gradient = (solver.density()[grid.index(last, centre, 0)] -
                                    solver.density()[grid.index(first, centre, 0)]) /
                                   (3.0 * (last - first));
  const double expected_gradient = -12.0 * solver.viscosity() * mean_velocity / (height * height);
  std::printf("inlet/outlet: pressure gradient %.4e, expected %.4e\n", pressure_gradient,
              expected_gradient);
  EXPECT_NEAR(pressure_gradient / expected_gradient, 1.0, 0.02);
}

}  // namespace
}  // namespace rbcsim::lattice
