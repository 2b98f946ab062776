// What the distributed lattice costs, for `rbcsim bench --ranks` (docs/performance.md). Measures,
// never asserts.
#pragma once

#include "common/vec3.hpp"
#include "parallel/communicator.hpp"

#include <array>
#include <cstddef>
#include <span>

namespace rbcsim::parallel {

struct DistributedFluidTiming {
  int processes = 1;
  int threads_per_process = 1;
  std::array<int, 3> lattice = {0, 0, 0};
  int block_planes = 0;
  double ms_per_step = 0.0;  // the fastest batch, between barriers: the slowest process's pace
  double mlups = 0.0;        // million node updates per second, all processes together
  // The largest over the processes, per step, in the fastest batch.
  double halo_ms_per_step = 0.0;
  double halo_bytes_per_step = 0.0;  // sent by one process
  double halo_messages_per_step = 0.0;
  int largest_slab_planes = 0;
  // With points: the immersed boundary's part of the step (stencils, spreading, the ghost
  // velocities and the interpolation with its gather and broadcast), the largest over processes.
  std::size_t points = 0;
  double ibm_ms_per_step = 0.0;
};

// Collective over `communicator`: a periodic nx * ny * nz box of plasma (TRT, the optimised
// kernel, a decaying shear wave) on the distributed lattice in blocks of `block_planes` planes,
// `threads` OpenMP threads per process; `batches` batches of `steps_per_batch` steps after a
// two-step warm-up, the fastest batch counting. With `points_lu` (the same on every process; phi2)
// every step also builds their stencils, spreads a small force from each and interpolates their
// velocities (they do not move). The result is the same on every process.
DistributedFluidTiming measure_distributed_fluid(const Communicator& communicator,
                                                 const std::array<int, 3>& lattice,
                                                 int block_planes, std::size_t steps_per_batch,
                                                 int batches, int threads,
                                                 std::span<const Vec3> points_lu = {});

// The same box on one undivided FluidSolver (no ghost planes, no exchange) in this process alone:
// the baseline the distributed lattice is measured against.
DistributedFluidTiming measure_undivided_fluid(const std::array<int, 3>& lattice,
                                               std::size_t steps_per_batch, int batches,
                                               int threads, std::span<const Vec3> points_lu = {});

}  // namespace rbcsim::parallel
