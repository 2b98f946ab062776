#include "ibm/benchmark.hpp"

#include <random>
#include <stdexcept>
#include <vector>

#include "common/fastest_batch.hpp"
#include "common/thread_count_scope.hpp"
#include "common/vec3.hpp"
#include "ibm/interpolation_stencil.hpp"
#include "ibm/point_advance.hpp"
#include "ibm/transfer.hpp"

namespace rbcsim::ibm {
namespace {

// Small enough that points stay inside a non-periodic grid over the whole measurement.
constexpr double kMaxVelocity_lu = 1e-5;

// The fields and points one benchmark step works on.
struct BenchmarkCase {
  std::vector<Vec3> positions, forces, velocities;
  std::vector<double> fx, fy, fz, ux, uy, uz;
};

BenchmarkCase random_case(std::size_t point_count, const GridView& grid) {
  std::mt19937_64 generator(20240521);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
  BenchmarkCase bench;
  // Points stay one spacing away from the faces, inside a non-periodic grid too.
  const Vec3 span(grid.nx - 2.0, grid.ny - 2.0, grid.nz - 2.0);
  for (std::size_t point = 0; point < point_count; ++point) {
    bench.positions.emplace_back(Vec3::Ones() + span.cwiseProduct(random_vec3(unit, generator)));
    bench.forces.push_back(random_vec3(symmetric, generator));
  }
  bench.velocities.resize(point_count);
  const std::size_t nodes = node_count(grid);
  for (auto* field : {&bench.fx, &bench.fy, &bench.fz}) field->assign(nodes, 0.0);
  for (auto* field : {&bench.ux, &bench.uy, &bench.uz}) {
    for (std::size_t node = 0; node < nodes; ++node) {
      field->push_back(kMaxVelocity_lu * symmetric(generator));
    }
  }
  return bench;
}

void ibm_step(BenchmarkCase& bench, InterpolationStencil& stencil, const GridView& grid,
              const DeltaKernel& kernel) {
  stencil.build(kernel, grid, bench.positions);
  spread_forces(stencil, bench.forces, grid, bench.fx.data(), bench.fy.data(), bench.fz.data());
  interpolate_velocity(stencil, grid, bench.ux.data(), bench.uy.data(), bench.uz.data(),
                       bench.velocities);
  advance_points(bench.positions, bench.velocities);
}

}  // namespace

double measure_ibm_step_us(std::size_t point_count, const GridView& grid, const DeltaKernel& kernel,
                           int threads) {
  if (threads < 1) throw std::invalid_argument("measure_ibm_step_us: threads must be >= 1");
  if (node_count(grid) == 0) throw std::invalid_argument("measure_ibm_step_us: empty grid");
  const ThreadCountScope thread_count(threads);

  BenchmarkCase bench = random_case(point_count, grid);
  InterpolationStencil stencil;
  ibm_step(bench, stencil, grid, kernel);  // warm-up: sizes the stencil's storage

  return 1e6 * fastest_batch_seconds_per_call([&] { ibm_step(bench, stencil, grid, kernel); });
}

}  // namespace rbcsim::ibm
