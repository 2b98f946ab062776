// Throughput of the fluid kernels, for `rbcsim bench` (docs/performance.md). Measures, never
// asserts.
#pragma once

#include <cstddef>

namespace rbcsim::lattice {

struct FluidThroughput {
  double optimised_mlups = 0.0;  // million fluid-node updates per second
  double reference_mlups = 0.0;
  double single_mlups = 0.0;  // the optimised kernel with single-precision populations
};

// Runs `steps` steps of each kernel (and of the optimised one in single precision) on a periodic nx * ny * nz box (TRT, a decaying shear wave,
// no force field) with `threads` OpenMP threads, after a two-step warm-up, and restores the
// previous thread count. Wall-clock time, so other load on the machine lowers the numbers.
FluidThroughput measure_fluid_mlups(int nx, int ny, int nz, std::size_t steps, int threads);

}  // namespace rbcsim::lattice
