// Timing of the membrane force kernels, for `rbcsim bench` (docs/performance.md: measure, never
// assert).
#pragma once

#include <string_view>

namespace rbcsim::membrane {

// Microseconds per force evaluation: MembraneModel::compute with ForceDetail::totals (what a time
// step calls), default parameters (Table 2 discocyte, all six terms, `gradient`), kernel `kernel`
// ("optimised" or "reference") on `threads` OpenMP threads, on the discocyte mesh at icosphere
// subdivision level `vertex_count_level` (10 4^N + 2 vertices: 3 -> 642, 4 -> 2562), stretched a
// little so that every term pushes. The best mean over short timed batches (a shared machine
// only ever slows a batch down); about 0.3 s of timing after the mesh is generated.
// Throws InputError for an unknown kernel, a level outside 0..7 or fewer than one thread.
double measure_membrane_force_us(int vertex_count_level, int threads, std::string_view kernel);

}  // namespace rbcsim::membrane
