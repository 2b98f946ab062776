// HDF5 snapshots with XDMF indexes (snapshot.hpp, add_hdf5_output): each process writes its own
// planes and cells into globally laid-out datasets.
#include <array>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "common/errors.hpp"
#include "coupling/series_entries.hpp"
#include "coupling/snapshot.hpp"
#include "io/xdmf_series.hpp"
#include "parallel/distributed_fluid.hpp"
#include "parallel/hdf5_file.hpp"

namespace rbcsim::coupling {
namespace {

using parallel::Hdf5File;
using Rows = Hdf5File::Rows;
using units::PhysicalUnit;

std::string h5_file(const char* kind, std::size_t step) {
  std::array<char, 48> text{};
  std::snprintf(text.data(), text.size(), "h5/%s_%09zu.h5", kind, step);
  return text.data();
}

void append(std::vector<double>& values, const Vec3& vector, double factor = 1.0) {
  values.insert(values.end(), {factor * vector.x(), factor * vector.y(), factor * vector.z()});
}
void append(std::vector<double>& values, std::span<const Vec3> vectors, double factor = 1.0) {
  for (const auto& vector : vectors) append(values, vector, factor);
}

// One time series: its .xdmf, rewritten after every snapshot, and the layout of its grids.
struct XdmfSeries {
  std::filesystem::path index;
  std::vector<io::XdmfEntry> entries;

  void add(const CoupledSimulation& simulation, const std::filesystem::path& directory,
           const std::string& file, const io::XdmfLayout& layout,
           std::span<const io::XdmfArray> arrays) {
    entries.push_back({simulation.time_s(), file});
    io::write_xdmf_series(directory / index, layout, arrays, entries);
  }
  // After a resume: the interrupted run's entries up to the restored state.
  void continue_existing(const CoupledSimulation& simulation,
                         const std::filesystem::path& directory) {
    entries = entries_up_to(directory / index, simulation.time_s(), &io::read_xdmf_series,
                            &io::XdmfEntry::time);
  }
};

struct Hdf5OutputState {
  std::filesystem::path directory;
  std::vector<std::int32_t> cell_kinds;  // empty: per-term forces instead of cell_kind
  XdmfSeries cells{"cells.xdmf", {}};
  XdmfSeries fluid{"fluid.xdmf", {}};
};

const parallel::Communicator& processes(const CoupledSimulation& simulation) {
  return simulation.parameters().processes;
}

// The h5/ directory, made by rank 0 before any process opens a file in it; a failure throws on
// every process.
void make_h5_directory(const Hdf5OutputState& state, const CoupledSimulation& simulation) {
  std::error_code made;
  if (processes(simulation).is_root()) {
    std::filesystem::create_directories(state.directory / "h5", made);
  }
  if (processes(simulation).any(static_cast<bool>(made))) {
    throw RuntimeFailure("hdf5 snapshot: cannot create " + (state.directory / "h5").string() +
                         (made ? ": " + made.message() : ""));
  }
}

// This process's cells, their rows in the global vertex and triangle order, and their values.
struct OwnedCells {
  std::vector<Rows> vertex_rows;
  std::vector<Rows> triangle_rows;
  std::size_t vertices = 0;  // of every cell
  std::size_t triangles = 0;
  std::vector<double> points_um, velocities_m_per_s, external_pN, total_pN, membrane_pN;
  std::vector<std::vector<double>> terms_pN;
  std::vector<std::int32_t> triangle_points, ids, kinds;
};

std::vector<std::string> term_names(const CoupledSimulation& simulation) {
  std::vector<std::string> names;
  if (simulation.cells().empty()) return names;
  for (const auto& term : simulation.cell(0).membrane_forces().terms) names.push_back(term.name);
  return names;
}

void append_cell(OwnedCells& owned, const CoupledSimulation& simulation, std::size_t k,
                 std::span<const std::int32_t> cell_kinds, std::size_t term_count) {
  const Cell& cell = simulation.cell(k);
  const double velocity_unit = simulation.units().to_physical(PhysicalUnit::velocity_m_per_s, 1.0);
  owned.vertex_rows.push_back({owned.vertices, cell.vertex_count()});
  owned.triangle_rows.push_back({owned.triangles, cell.model().triangles().size()});
  for (const auto& triangle : cell.model().triangles()) {
    for (const auto vertex : triangle) {
      owned.triangle_points.push_back(static_cast<std::int32_t>(owned.vertices) + vertex);
    }
  }
  for (const auto& position : cell.positions_lu()) {
    append(owned.points_um, simulation.frame().to_um(position));
  }
  append(owned.velocities_m_per_s, cell.velocities_lu(), velocity_unit);
  append(owned.external_pN, cell.external_forces_pN());
  append(owned.total_pN, cell.total_forces_pN());
  owned.ids.insert(owned.ids.end(), cell.vertex_count(), static_cast<std::int32_t>(k));
  if (!cell_kinds.empty()) {
    owned.kinds.insert(owned.kinds.end(), cell.vertex_count(), cell_kinds[k]);
    return;
  }
  append(owned.membrane_pN, cell.membrane_forces().total_pN);
  const auto& terms = cell.membrane_forces().terms;
  if (terms.size() != term_count) {
    throw std::logic_error("hdf5 snapshot: cell " + std::to_string(k) + " has " +
                           std::to_string(terms.size()) + " force terms, cell 0 " +
                           std::to_string(term_count));
  }
  for (std::size_t t = 0; t < term_count; ++t) append(owned.terms_pN[t], terms[t].forces_pN);
}

OwnedCells owned_cells(const CoupledSimulation& simulation,
                       std::span<const std::int32_t> cell_kinds, std::size_t term_count) {
  OwnedCells owned;
  owned.terms_pN.resize(term_count);
  for (std::size_t k = 0; k < simulation.cells().size(); ++k) {
    if (simulation.owns_cell(k)) append_cell(owned, simulation, k, cell_kinds, term_count);
    owned.vertices += simulation.cell(k).vertex_count();
    owned.triangles += simulation.cell(k).model().triangles().size();
  }
  return owned;
}

void write_cells(Hdf5OutputState& state, const CoupledSimulation& simulation) {
  make_h5_directory(state, simulation);
  const auto names = term_names(simulation);
  const std::size_t term_count = state.cell_kinds.empty() ? names.size() : 0;
  const OwnedCells owned = owned_cells(simulation, state.cell_kinds, term_count);
  const std::array<std::size_t, 2> vectors{owned.vertices, 3};
  const std::array<std::size_t, 1> scalars{owned.vertices};
  const std::array<std::size_t, 2> triangles{owned.triangles, 3};
  std::vector<io::XdmfArray> arrays;
  const std::string file = h5_file("cells", simulation.time_step());
  Hdf5File h5(processes(simulation), state.directory / file);
  h5.write_rows("points_um", vectors, owned.vertex_rows, std::span<const double>(owned.points_um));
  h5.write_rows("triangles", triangles, owned.triangle_rows,
                std::span<const std::int32_t>(owned.triangle_points));
  const auto vector_array = [&](const std::string& name, const std::vector<double>& values) {
    h5.write_rows(name, vectors, owned.vertex_rows, std::span<const double>(values));
    arrays.push_back({name, 3, io::XdmfNumber::float64});
  };
  const auto integer_array = [&](const std::string& name, const std::vector<std::int32_t>& values) {
    h5.write_rows(name, scalars, owned.vertex_rows, std::span<const std::int32_t>(values));
    arrays.push_back({name, 1, io::XdmfNumber::int32});
  };
  integer_array("cell_id", owned.ids);
  if (!state.cell_kinds.empty()) integer_array("cell_kind", owned.kinds);
  for (std::size_t t = 0; t < term_count; ++t) {
    vector_array("force_" + names[t] + "_pN", owned.terms_pN[t]);
  }
  if (state.cell_kinds.empty()) vector_array("membrane_force_pN", owned.membrane_pN);
  vector_array("external_force_pN", owned.external_pN);
  vector_array("total_force_pN", owned.total_pN);
  vector_array("velocity_m_per_s", owned.velocities_m_per_s);
  h5.close();
  state.cells.add(simulation, state.directory, file,
                  io::XdmfTriangles{owned.vertices, owned.triangles, "points_um", "triangles"},
                  arrays);
}

// The fluid's planes [z_begin, z_end) on this process and the solver holding them, whose nodes
// they are from first_node on, one after the other (x fastest, plane after plane, in the
// undivided solver and in a slab alike).
struct FluidPlanes {
  const lattice::FluidSolver* solver = nullptr;
  int z_begin = 0;
  int z_end = 0;
  std::size_t first_node = 0;
};

FluidPlanes fluid_planes(const CoupledSimulation& simulation) {
  if (const auto* distributed = simulation.distributed_fluid()) {
    return {&distributed->local(), distributed->z_begin(), distributed->z_end(),
            distributed->local_node(0, 0, distributed->z_begin())};
  }
  const auto& fluid = simulation.fluid();
  return {&fluid, 0, fluid.grid().nz(), 0};
}

void write_fluid(Hdf5OutputState& state, const CoupledSimulation& simulation) {
  make_h5_directory(state, simulation);
  const FluidPlanes planes = fluid_planes(simulation);
  const ibm::GridView& grid = simulation.grid_view();
  const double velocity_unit = simulation.units().to_physical(PhysicalUnit::velocity_m_per_s, 1.0);
  const double density_unit = simulation.units().to_physical(PhysicalUnit::density_kg_per_m3, 1.0);
  std::vector<double> velocity;
  std::vector<double> density;
  std::vector<std::uint8_t> mask;
  const auto& solver = *planes.solver;
  const std::size_t end =
      planes.first_node + static_cast<std::size_t>(planes.z_end - planes.z_begin) *
                              static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny);
  for (std::size_t node = planes.first_node; node < end; ++node) {
    for (int c = 0; c < 3; ++c) velocity.push_back(velocity_unit * solver.velocity()[c][node]);
    density.push_back(density_unit * solver.density()[node]);
    mask.push_back(solver.solid_mask()[node]);
  }
  const auto nz = static_cast<std::size_t>(grid.nz);
  const auto ny = static_cast<std::size_t>(grid.ny);
  const auto nx = static_cast<std::size_t>(grid.nx);
  const std::array<std::size_t, 4> vectors{nz, ny, nx, 3};
  const std::array<std::size_t, 3> scalars{nz, ny, nx};
  const std::array<Rows, 1> rows{Rows{static_cast<std::size_t>(planes.z_begin),
                                      static_cast<std::size_t>(planes.z_end - planes.z_begin)}};
  const std::string file = h5_file("fluid", simulation.time_step());
  Hdf5File h5(processes(simulation), state.directory / file);
  h5.write_rows("velocity_m_per_s", vectors, rows, std::span<const double>(velocity));
  h5.write_rows("density_kg_per_m3", scalars, rows, std::span<const double>(density));
  h5.write_rows("solid_mask", scalars, rows, std::span<const std::uint8_t>(mask));
  h5.close();
  const auto& frame = simulation.frame();
  const std::vector<io::XdmfArray> arrays = {{"velocity_m_per_s", 3, io::XdmfNumber::float64},
                                             {"density_kg_per_m3", 1, io::XdmfNumber::float64},
                                             {"solid_mask", 1, io::XdmfNumber::uint8}};
  state.fluid.add(simulation, state.directory, file,
                  io::XdmfImage{{nx, ny, nz},
                                {frame.origin_um.x(), frame.origin_um.y(), frame.origin_um.z()},
                                frame.dx_um},
                  arrays);
}

}  // namespace

void add_hdf5_output(CoupledSimulation& simulation, const std::filesystem::path& directory,
                     const SnapshotIntervals& intervals, std::span<const std::int32_t> cell_kinds) {
  auto state = std::make_shared<Hdf5OutputState>();
  state->directory = directory;
  state->cell_kinds.assign(cell_kinds.begin(), cell_kinds.end());
  if (intervals.membrane_steps > 0) {
    simulation.add_observer({"hdf5_membrane", intervals.membrane_steps,
                             [state](const CoupledSimulation& s) { write_cells(*state, s); },
                             [state](const CoupledSimulation& s) {
                               state->cells.continue_existing(s, state->directory);
                             },
                             /*needs_term_forces=*/cell_kinds.empty()});
  }
  if (intervals.fluid_steps > 0) {
    simulation.add_observer({"hdf5_fluid", intervals.fluid_steps,
                             [state](const CoupledSimulation& s) { write_fluid(*state, s); },
                             [state](const CoupledSimulation& s) {
                               state->fluid.continue_existing(s, state->directory);
                             },
                             /*needs_term_forces=*/false, /*reads_fluid=*/false});
  }
}

}  // namespace rbcsim::coupling
