#include "coupling/snapshot.hpp"

#include <array>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "coupling/series_entries.hpp"
#include "io/atomic_file.hpp"
#include "io/pvd_collection.hpp"
#include "io/vtk_image_data.hpp"
#include "io/vtk_polydata.hpp"

namespace rbcsim::coupling {
namespace {

using units::PhysicalUnit;

std::vector<Vec3> scaled(std::span<const Vec3> values, double factor) {
  std::vector<Vec3> result(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) result[i] = factor * values[i];
  return result;
}

std::string cell_name(std::size_t cell_index) { return "cell" + std::to_string(cell_index); }

std::string step_suffix(std::size_t step) {
  std::array<char, 24> text{};
  std::snprintf(text.data(), text.size(), "_%09zu", step);
  return text.data();
}

// The files of one series and its collection, rewritten after every snapshot.
struct Series {
  std::filesystem::path collection;
  std::vector<io::PvdEntry> entries;

  void add(const CoupledSimulation& simulation, const std::filesystem::path& directory,
           const std::string& file) {
    entries.push_back({simulation.time_s(), file});
    io::write_pvd_collection(directory / collection, entries);
  }

  // After a resume: the interrupted run's entries up to the restored state.
  void continue_existing(const CoupledSimulation& simulation,
                         const std::filesystem::path& directory) {
    entries = entries_up_to(directory / collection, simulation.time_s(), &io::read_pvd_collection,
                            &io::PvdEntry::timestep);
  }
};

struct VtkOutputState {
  std::filesystem::path directory;
  std::vector<Series> cells;
  Series fluid{"fluid.pvd", {}};
  std::vector<std::int32_t> cell_kinds;  // non-empty: all cells in `together`
  Series together{"cells.pvd", {}};
};

void add_cell_series(VtkOutputState& state, const CoupledSimulation& simulation) {
  while (state.cells.size() < simulation.cells().size()) {
    state.cells.push_back({cell_name(state.cells.size()) + ".pvd", {}});
  }
}

void continue_membranes(VtkOutputState& state, const CoupledSimulation& simulation) {
  if (!state.cell_kinds.empty()) {
    state.together.continue_existing(simulation, state.directory);
    return;
  }
  add_cell_series(state, simulation);
  for (auto& series : state.cells) series.continue_existing(simulation, state.directory);
}

void continue_fluid(VtkOutputState& state, const CoupledSimulation& simulation) {
  state.fluid.continue_existing(simulation, state.directory);
}

void write_membranes(VtkOutputState& state, const CoupledSimulation& simulation) {
  std::filesystem::create_directories(state.directory / "vtk");
  if (!state.cell_kinds.empty()) {
    const std::string file = "vtk/cells" + step_suffix(simulation.time_step()) + ".vtp";
    write_cells_snapshot(state.directory / file, simulation, state.cell_kinds);
    state.together.add(simulation, state.directory, file);
    return;
  }
  add_cell_series(state, simulation);
  for (std::size_t k = 0; k < simulation.cells().size(); ++k) {
    const std::string file = "vtk/" + cell_name(k) + step_suffix(simulation.time_step()) + ".vtp";
    write_cell_snapshot(state.directory / file, simulation, k);
    state.cells[k].add(simulation, state.directory, file);
  }
}

void write_fluid(VtkOutputState& state, const CoupledSimulation& simulation) {
  std::filesystem::create_directories(state.directory / "vtk");
  const std::string file = "vtk/fluid" + step_suffix(simulation.time_step()) + ".vti";
  write_fluid_snapshot(state.directory / file, simulation);
  state.fluid.add(simulation, state.directory, file);
}

}  // namespace

void write_cell_snapshot(const std::filesystem::path& path, const CoupledSimulation& simulation,
                         std::size_t cell_index) {
  const Cell& cell = simulation.cell(cell_index);
  std::vector<Vec3> positions_um(cell.vertex_count());
  for (std::size_t v = 0; v < positions_um.size(); ++v) {
    positions_um[v] = simulation.frame().to_um(cell.positions_lu()[v]);
  }
  const auto velocities_m_per_s = scaled(
      cell.velocities_lu(), simulation.units().to_physical(PhysicalUnit::velocity_m_per_s, 1.0));
  std::vector<io::PointDataArray> arrays;
  // Each term's forces when the step has them (CoupledSimulation::add_term_forces; a failure
  // dump of a step whose forces could not be evaluated has only the totals).
  for (const auto& term : cell.membrane_forces().terms) {
    if (term.forces_pN.size() != cell.vertex_count()) continue;
    arrays.push_back(io::vector_point_array("force_" + term.name + "_pN", term.forces_pN));
  }
  arrays.push_back(io::vector_point_array("membrane_force_pN", cell.membrane_forces().total_pN));
  arrays.push_back(io::vector_point_array("external_force_pN", cell.external_forces_pN()));
  arrays.push_back(io::vector_point_array("total_force_pN", cell.total_forces_pN()));
  arrays.push_back(io::vector_point_array("velocity_m_per_s", velocities_m_per_s));
  io::write_vtk_polydata(path, positions_um, cell.model().triangles(), arrays,
                         io::VtkEncoding::base64);
}

void write_cells_snapshot(const std::filesystem::path& path, const CoupledSimulation& simulation,
                          std::span<const std::int32_t> cell_kinds) {
  const double velocity_unit = simulation.units().to_physical(PhysicalUnit::velocity_m_per_s, 1.0);
  std::vector<Vec3> positions_um;
  std::vector<Vec3> velocities_m_per_s;
  std::vector<Vec3> total_forces_pN;
  std::vector<Vec3> external_forces_pN;
  std::vector<std::int32_t> ids;
  std::vector<std::int32_t> kinds;
  std::vector<std::array<std::int32_t, 3>> triangles;
  for (std::size_t k = 0; k < simulation.cells().size(); ++k) {
    const Cell& cell = simulation.cell(k);
    const auto offset = static_cast<std::int32_t>(positions_um.size());
    for (const auto& triangle : cell.model().triangles()) {
      triangles.push_back({triangle[0] + offset, triangle[1] + offset, triangle[2] + offset});
    }
    for (std::size_t v = 0; v < cell.vertex_count(); ++v) {
      positions_um.push_back(simulation.frame().to_um(cell.positions_lu()[v]));
      velocities_m_per_s.push_back(velocity_unit * cell.velocities_lu()[v]);
      ids.push_back(static_cast<std::int32_t>(k));
      kinds.push_back(cell_kinds[k]);
    }
    const auto total = cell.total_forces_pN();
    total_forces_pN.insert(total_forces_pN.end(), total.begin(), total.end());
    const auto external = cell.external_forces_pN();
    external_forces_pN.insert(external_forces_pN.end(), external.begin(), external.end());
  }
  const std::vector<io::PointDataArray> arrays = {
      io::PointDataArray{"cell_id", 1, std::span<const std::int32_t>(ids)},
      io::PointDataArray{"cell_kind", 1, std::span<const std::int32_t>(kinds)},
      io::vector_point_array("external_force_pN", external_forces_pN),
      io::vector_point_array("total_force_pN", total_forces_pN),
      io::vector_point_array("velocity_m_per_s", velocities_m_per_s)};
  io::write_vtk_polydata(path, positions_um, triangles, arrays, io::VtkEncoding::base64);
}

void write_fluid_snapshot(const std::filesystem::path& path, const CoupledSimulation& simulation) {
  const auto& fluid = simulation.fluid();
  const auto& grid = fluid.grid();
  const std::size_t node_count = grid.node_count();
  const double velocity_unit = simulation.units().to_physical(PhysicalUnit::velocity_m_per_s, 1.0);
  std::vector<Vec3> velocity_m_per_s(node_count);
  std::vector<double> density_kg_per_m3(node_count);
  const double density_unit = simulation.units().to_physical(PhysicalUnit::density_kg_per_m3, 1.0);
  for (std::size_t node = 0; node < node_count; ++node) {
    velocity_m_per_s[node] =
        velocity_unit *
        Vec3(fluid.velocity()[0][node], fluid.velocity()[1][node], fluid.velocity()[2][node]);
    density_kg_per_m3[node] = density_unit * fluid.density()[node];
  }
  const std::vector<io::PointDataArray> arrays = {
      io::vector_point_array("velocity_m_per_s", velocity_m_per_s),
      io::scalar_point_array("density_kg_per_m3", density_kg_per_m3),
      io::byte_point_array("solid_mask", fluid.solid_mask())};
  const io::ImageGrid image{
      {grid.nx(), grid.ny(), grid.nz()}, simulation.frame().origin_um, simulation.frame().dx_um};
  io::write_vtk_image_data(path, image, arrays);
}

void add_vtk_output(CoupledSimulation& simulation, const std::filesystem::path& directory,
                    const SnapshotIntervals& intervals, std::span<const std::int32_t> cell_kinds) {
  auto state = std::make_shared<VtkOutputState>();
  state->directory = directory;
  state->cell_kinds.assign(cell_kinds.begin(), cell_kinds.end());
  if (intervals.membrane_steps > 0) {
    simulation.add_observer(
        {"vtk_membrane", intervals.membrane_steps,
         [state](const CoupledSimulation& s) { write_membranes(*state, s); },
         [state](const CoupledSimulation& s) { continue_membranes(*state, s); },
         /*needs_term_forces=*/cell_kinds.empty()});
  }
  if (intervals.fluid_steps > 0) {
    simulation.add_observer({"vtk_fluid", intervals.fluid_steps,
                             [state](const CoupledSimulation& s) { write_fluid(*state, s); },
                             [state](const CoupledSimulation& s) { continue_fluid(*state, s); },
                             /*needs_term_forces=*/false, /*reads_fluid=*/true});
  }
}

std::string membrane_series_file(SnapshotFormat format, bool suspension) {
  if (format == SnapshotFormat::hdf5) return "cells.xdmf";
  return suspension ? "cells.pvd" : "cell0.pvd";
}

std::string fluid_series_file(SnapshotFormat format) {
  return format == SnapshotFormat::hdf5 ? "fluid.xdmf" : "fluid.pvd";
}

void add_snapshot_output(CoupledSimulation& simulation, const std::filesystem::path& directory,
                         const SnapshotIntervals& intervals,
                         std::span<const std::int32_t> cell_kinds) {
  if (intervals.format == SnapshotFormat::hdf5) {
    add_hdf5_output(simulation, directory, intervals, cell_kinds);
  } else {
    add_vtk_output(simulation, directory, intervals, cell_kinds);
  }
}

void write_failure_dump(const std::filesystem::path& directory, const CoupledSimulation& simulation,
                        std::optional<std::size_t> cell, const std::string& reason) {
  std::filesystem::create_directories(directory);
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < simulation.cells().size(); ++k) {
    write_cell_snapshot(directory / (cell_name(k) + ".vtp"), simulation, k);
    files.push_back(cell_name(k) + ".vtp");
  }
  write_fluid_snapshot(directory / "fluid.vti", simulation);
  files.push_back("fluid.vti");
  const nlohmann::ordered_json failure = {
      {"step", simulation.time_step() + 1},
      {"time_s", simulation.time_s()},
      {"cell", cell ? nlohmann::ordered_json(*cell) : nlohmann::ordered_json(nullptr)},
      {"reason", reason},
      {"files", files}};
  io::write_text_atomically(directory / "failure.json", failure.dump(2) + "\n");
}

}  // namespace rbcsim::coupling
