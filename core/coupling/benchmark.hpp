// Measurements behind `rbcsim bench` (docs/performance.md): the machine, its memory bandwidth, and
// the cost of one coupled step. Measure, don't assert: wall-clock times, so other processes on the
// machine lower the numbers (the fastest of several batches is reported to limit that).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "contact/cell_repulsion.hpp"
#include "coupling/coupled_simulation.hpp"
#include "membrane/parameters.hpp"
#include "mesh/triangle_mesh.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::coupling {

struct MachineDescription {
  std::string cpu_model;  // /proc/cpuinfo "model name"; "unknown" if absent
  int logical_cpus = 0;
  int openmp_max_threads = 0;
  std::string omp_wait_policy;             // the environment's OMP_WAIT_POLICY, "unset" if absent
  std::string load_average;                // /proc/loadavg: 1, 5 and 15 minutes; "" if absent
  std::size_t last_level_cache_bytes = 0;  // from /sys, else glibc (0 if unknown)
};

MachineDescription describe_machine();

// A periodic lattice whose fluid arrays (19 populations plus density, velocity and force density:
// 208 bytes per node in double precision) fill at least twice the last-level cache: nx x 128 x
// 128 with nx a multiple of 8 (at least 128). 256 x 128 x 128 when the cache size is unknown (0).
std::array<int, 3> lattice_beyond_cache(std::size_t last_level_cache_bytes);

// STREAM triad a[i] = b[i] + s c[i] on three arrays of `elements` doubles with `threads` OpenMP
// threads: the fastest pass, in GB/s, counting 24 bytes per element as STREAM does (the
// write-allocate read of a[i] is not counted). Throws std::invalid_argument for threads < 1 or
// no elements.
double measure_triad_bandwidth_GB_per_s(std::size_t elements, int threads);

struct CoupledStepTiming {
  std::size_t vertex_count = 0;
  double ms_per_step = 0.0;  // the fastest batch
  // Seconds spent in each phase during that batch of fastest_batch_phases.steps steps.
  StepPhaseTimes fastest_batch_phases;
};

// The cytoplasm viscosity contrast of a measured step: a ratio other than 1 adds the indicator
// (recomputed at the given cadence, CouplingParameters::cytoplasm_update_lu) and per-node rates.
struct CytoplasmSettings {
  double viscosity_ratio = 1.0;
  double update_lu = CouplingParameters{}.cytoplasm_update_lu;
};

// One cell (`cell_mesh`, its own stress-free reference, centred in the box) in a periodic box of
// `extent` nodes whose fluid starts as a shear wave, with the given lattice units (dx, tau) and
// membrane parameters and IBM kernel; timed after one warm-up step on `threads` threads. Restores
// the OpenMP thread count. Throws InputError if the cell does not fit the box.
CoupledStepTiming measure_coupled_step(const mesh::TriangleMesh& cell_mesh,
                                       const membrane::MembraneParameters& membrane_parameters,
                                       const units::UnitConverter& units,
                                       const std::array<int, 3>& extent,
                                       std::string_view ibm_kernel, int threads,
                                       const CytoplasmSettings& cytoplasm = {});

struct SuspensionStepTiming {
  std::size_t cell_count = 0;
  std::size_t vertex_count = 0;  // of all cells
  std::array<int, 3> lattice{};
  double ms_per_step = 0.0;  // the fastest batch
  StepPhaseTimes fastest_batch_phases;
  // Vertex pairs of different cells within the contact range in the last step: the contact search
  // had work to do.
  std::size_t contact_pairs = 0;
};

// The block of nodes each cell of measure_suspension_step gets: the cell's bounding box plus
// 2 nodes on either side across the row (room for a 4-point kernel), and along the row plus half
// the contact range, so that neighbours face each other inside the range.
std::array<int, 3> suspension_block_nodes(const mesh::TriangleMesh& cell_mesh, double dx_um,
                                          double contact_range_um);

// `cell_count` copies of `cell_mesh`, each centred in its own block (suspension_block_nodes), the
// blocks in a row along x in a periodic box whose fluid starts as a shear wave, with contact on:
// the fluid, the vertices and the contact pairs all grow in proportion to the count, so a step
// whose cost is linear in the cells costs the same per cell at every count. Timed after one
// warm-up step on `threads` threads; restores the OpenMP thread count. Throws InputError for no
// cells.
SuspensionStepTiming measure_suspension_step(
    const mesh::TriangleMesh& cell_mesh, const membrane::MembraneParameters& membrane_parameters,
    const units::UnitConverter& units, const contact::ContactParameters& contact,
    std::size_t cell_count, std::string_view ibm_kernel, int threads);

}  // namespace rbcsim::coupling
