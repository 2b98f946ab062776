// lattice.*, physics.cytoplasm_viscosity_ratio, ibm.*, stability.* and output.* options -> the
// fluid's and the coupled time loop's parameter structs (lattice units where the engine wants
// them).
#pragma once

#include <filesystem>

#include "config/config.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling/snapshot.hpp"
#include "lattice/fluid_solver.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::setup {

// Collision model, relaxation time and TRT magic parameter, kernel and wall rule, and the
// cytoplasm's viscosity ratio.
lattice::FluidParameters fluid_parameters_from(const config::Config& config);

// IBM kernel and point advance, stability limits, where failure dumps go, and the processes of
// the run (every process mpirun started; one without it) with lattice.block_planes.
coupling::CouplingParameters coupling_parameters_from(const config::Config& config,
                                                      const std::filesystem::path& run_directory);

// output.format resolved for a run writing its snapshots into `directory` (auto: the format of the
// series already there when resuming, so that a run resumed on another process count goes on in
// its own; otherwise hdf5 across processes when built with it, else vtk). InputError naming
// output.format for hdf5 in a build without it.
coupling::SnapshotFormat snapshot_format_from(const config::Config& config,
                                              const std::filesystem::path& directory = {});
// Snapshot intervals in steps: each output.*_interval_s rounded to the nearest whole number of
// steps (at least one); 0 stays 0 (no snapshots). With the format of snapshot_format_from.
coupling::SnapshotIntervals snapshot_intervals_from(const config::Config& config,
                                                    const units::UnitConverter& units,
                                                    const std::filesystem::path& directory = {});

}  // namespace rbcsim::setup
