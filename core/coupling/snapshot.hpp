// ParaView output of a coupled simulation (docs/architecture.md, "Output files"), written
// atomically through core/io:
//   membrane  VTK PolyData (.vtp), positions in um, per-vertex arrays
//               force_<term>_pN     each enabled membrane term (unclamped)
//               membrane_force_pN   their sum, after the vertex force cap
//               external_force_pN   the hooks' forces (tweezers)
//               total_force_pN      membrane + external: what the IBM spread
//               velocity_m_per_s    the interpolated fluid velocity
//             (forces and velocity of the latest step, at the positions one step earlier);
//   fluid     VTK ImageData (.vti) on the lattice nodes, in um like the membrane:
//               velocity_m_per_s, density_kg_per_m3 (0 at non-fluid nodes), solid_mask (the
//               lattice's node kinds: 0 fluid, 1 wall, 2 pressure outlet);
//   series    one .pvd collection per cell and one for the fluid, time in seconds; for a
//             suspension (add_vtk_output's cell_kinds) one collection, cells.pvd, whose
//             .vtp files hold every cell, with the per-vertex arrays cell_id and cell_kind
//             (an index into the run's morphologies) besides velocity and forces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>
#include <filesystem>
#include <optional>
#include <string>

#include "coupling/coupled_simulation.hpp"

namespace rbcsim::coupling {

void write_cell_snapshot(const std::filesystem::path& path, const CoupledSimulation& simulation,
                         std::size_t cell_index);
void write_fluid_snapshot(const std::filesystem::path& path, const CoupledSimulation& simulation);

// The files of a snapshot: VTK (.vtp, .vti and .pvd, written by rank 0 from gathered copies
// across processes) or HDF5 with XDMF indexes (each process writing its part; below).
enum class SnapshotFormat { vtk, hdf5 };

// Snapshot intervals in steps; 0: none of that kind.
struct SnapshotIntervals {
  std::size_t membrane_steps = 0;
  std::size_t fluid_steps = 0;
  SnapshotFormat format = SnapshotFormat::vtk;
};

// Every cell in one polydata (vertices numbered cell after cell), with cell_id and cell_kind.
void write_cells_snapshot(const std::filesystem::path& path, const CoupledSimulation& simulation,
                          std::span<const std::int32_t> cell_kinds);

// Registers the observers "vtk_membrane" and "vtk_fluid", which write
// <directory>/vtk/cell<K>_<step>.vtp and <directory>/vtk/fluid_<step>.vti and rewrite
// <directory>/cell<K>.pvd and <directory>/fluid.pvd after each snapshot, so that an interrupted
// run still leaves a valid collection. After a resume (CoupledSimulation::resume_from) the
// collections go on from the interrupted run's, up to the restored state.
// With `cell_kinds` (one per cell, e.g. the morphology's index): all cells in one series,
// <directory>/cells.pvd of vtk/cells_<step>.vtp, instead of one per cell.
void add_vtk_output(CoupledSimulation& simulation, const std::filesystem::path& directory,
                    const SnapshotIntervals& intervals,
                    std::span<const std::int32_t> cell_kinds = {});

// Registers the observers "hdf5_membrane" and "hdf5_fluid", which write
// <directory>/h5/cells_<step>.h5 and <directory>/h5/fluid_<step>.h5 (parallel/hdf5_file.hpp) and
// rewrite the time series <directory>/cells.xdmf and <directory>/fluid.xdmf after each snapshot
// (io/xdmf_series.hpp; continued after a resume as the .pvd are). Nothing is gathered: each
// process writes the planes of its slab and the cells it owns (CoupledSimulation::owns_cell), into
// datasets laid out by global plane and by cell id, so the files are the same on any process
// count. Datasets, in the units of their names:
//   fluid  velocity_m_per_s {nz, ny, nx, 3}, density_kg_per_m3 {nz, ny, nx}, solid_mask
//          {nz, ny, nx} (uint8; the lattice's node kinds as in the .vti);
//   cells  points_um {V, 3} (every cell's vertices, cell after cell), triangles {T, 3} (int32,
//          indices into points_um), cell_id {V} (int32), velocity_m_per_s, external_force_pN,
//          total_force_pN {V, 3}; with `cell_kinds` also cell_kind {V} (int32), without it
//          membrane_force_pN and force_<term>_pN of every enabled term {V, 3}.
void add_hdf5_output(CoupledSimulation& simulation, const std::filesystem::path& directory,
                     const SnapshotIntervals& intervals,
                     std::span<const std::int32_t> cell_kinds = {});

// The series a run's snapshots are listed in, relative to its directory: the membrane's
// (cell0.pvd for one cell's own series, cells.pvd for a suspension's, cells.xdmf) and the fluid's.
std::string membrane_series_file(SnapshotFormat format, bool suspension);
std::string fluid_series_file(SnapshotFormat format);

// add_vtk_output or add_hdf5_output, as intervals.format says.
void add_snapshot_output(CoupledSimulation& simulation, const std::filesystem::path& directory,
                         const SnapshotIntervals& intervals,
                         std::span<const std::int32_t> cell_kinds = {});

// The diagnosis dump of a failed step into <directory>: cell<K>.vtp for every cell, fluid.vti,
// and failure.json {"step", "time_s", "cell" (or null), "reason", "files"}.
void write_failure_dump(const std::filesystem::path& directory, const CoupledSimulation& simulation,
                        std::optional<std::size_t> cell, const std::string& reason);

}  // namespace rbcsim::coupling
