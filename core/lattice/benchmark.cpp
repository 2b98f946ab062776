#include "lattice/benchmark.hpp"

#include "lattice/fluid_solver.hpp"

#include "common/thread_count_scope.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

namespace rbcsim::lattice {
namespace {

double kernel_mlups(const LatticeGrid& grid, const char* kernel, std::size_t steps,
                    Precision precision = Precision::double_precision) {
  FluidParameters parameters;
  parameters.kernel = kernel;
  parameters.precision = precision;
  FluidSolver solver(grid, parameters);
  const std::size_t node_count = grid.node_count();
  VectorField velocity{std::vector<double>(node_count, 0.0), std::vector<double>(node_count, 0.0),
                       std::vector<double>(node_count, 0.0)};
  for (std::size_t node = 0; node < node_count; ++node) {
    const int y = grid.coordinates(node)[1];
    velocity[0][node] = 0.01 * std::sin(2.0 * std::numbers::pi * y / grid.ny());
  }
  solver.initialise_equilibrium(std::vector<double>(node_count, 1.0), velocity);
  solver.advance(2);
  const auto start = std::chrono::steady_clock::now();
  solver.advance(steps);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  return static_cast<double>(node_count) * static_cast<double>(steps) / elapsed.count() / 1e6;
}

}  // namespace

FluidThroughput measure_fluid_mlups(int nx, int ny, int nz, std::size_t steps, int threads) {
  const ThreadCountScope thread_count(threads);
  const LatticeGrid grid(nx, ny, nz);
  FluidThroughput throughput;
  throughput.optimised_mlups = kernel_mlups(grid, "optimised", steps);
  throughput.reference_mlups = kernel_mlups(grid, "reference", steps);
  throughput.single_mlups = kernel_mlups(grid, "optimised", steps, Precision::single_precision);
  return throughput;
}

}  // namespace rbcsim::lattice
