// Timing of the immersed-boundary part of one coupled step, for `rbcsim bench`
// (docs/performance.md): measure, don't assert.
#pragma once

#include <cstddef>

#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"

namespace rbcsim::ibm {

// Wall time in microseconds of one IBM step — build the stencil, spread the point forces,
// interpolate the velocity, advance the points (forward Euler) — for `point_count` points placed
// uniformly at random (fixed seed) in `grid`, with random forces and a random small velocity
// field, on `threads` OpenMP threads: the fastest of batches of 5 steps run for about a quarter
// of a second after one warm-up step (robust to other processes on the machine). Restores the
// previous OpenMP thread count. Throws std::invalid_argument for threads < 1 or an
// empty grid.
double measure_ibm_step_us(std::size_t point_count, const GridView& grid, const DeltaKernel& kernel,
                           int threads);

}  // namespace rbcsim::ibm
