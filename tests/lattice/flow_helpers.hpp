// Shared set-ups and error measures for the lattice tests. Analytic solutions live in the tests
// themselves, never here, so that each test states the physics it checks.
#pragma once

#include "lattice/fluid_solver.hpp"

#include <cmath>
#include <cstddef>
#include <functional>

namespace rbcsim::lattice::testing {

// Walls in the planes y = 0 and y = ny - 1 (half-way walls at y = 1/2 and y = ny - 3/2), the top
// one moving at `top_velocity`.
inline void add_channel_walls(FluidSolver& solver,
                              const std::array<double, 3>& top_velocity = {0.0, 0.0, 0.0}) {
  const LatticeGrid& grid = solver.grid();
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) {
      solver.set_wall(grid.index(x, 0, z));
      solver.set_wall(grid.index(x, grid.ny() - 1, z), top_velocity);
    }
  }
}

// Relative L2 error of the x-velocity over the fluid nodes:
// sqrt(sum (u - u_exact)^2 / sum u_exact^2), u_exact(x, y, z) given by `exact`.
inline double relative_l2_error_x(const FluidSolver& solver,
                                  const std::function<double(int, int, int)>& exact) {
  const LatticeGrid& grid = solver.grid();
  double error_squared = 0.0;
  double norm_squared = 0.0;
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    if (!solver.boundaries().is_fluid(node)) {
      continue;
    }
    const auto [x, y, z] = grid.coordinates(node);
    const double expected = exact(x, y, z);
    const double difference = solver.velocity()[0][node] - expected;
    error_squared += difference * difference;
    norm_squared += expected * expected;
  }
  return std::sqrt(error_squared / norm_squared);
}

// Projection of u_x onto the Taylor-Green vortex mode -cos kx sin ky.
inline double vortex_amplitude(const FluidSolver& solver, double wavenumber) {
  const LatticeGrid& grid = solver.grid();
  double projection = 0.0;
  double norm = 0.0;
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    const auto [x, y, z] = grid.coordinates(node);
    const double mode = -std::cos(wavenumber * x) * std::sin(wavenumber * y);
    projection += solver.velocity()[0][node] * mode;
    norm += mode * mode;
  }
  return projection / norm;
}

}  // namespace rbcsim::lattice::testing
