#include "cases/sheared_suspension.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "cases/capillary_observables.hpp"
#include "cases/json_values.hpp"
#include "cases/release_orientations.hpp"
#include "cases/shear_case.hpp"
#include "cases/wall_repulsion.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/state_archive.hpp"
#include "lattice/d3q19.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::cases {
namespace {

using units::PhysicalUnit;

void require_positive_sheared(double value, const char* option) {
  if (!(value > 0.0)) throw InputError(option, "must be > 0");
}

void validate_sheared(const ShearedSuspensionSettings& settings) {
  require_positive_sheared(settings.gap_um, "shear.gap_diameters");
  require_positive_sheared(settings.length_um, "shear.width_diameters");
  require_positive_sheared(settings.width_um, "shear.width_diameters");
  require_positive_sheared(settings.shear_rate_per_s, "shear.rates_per_s");
  require_positive_sheared(settings.strain, "suspension.strain");
  require_positive_sheared(settings.sample_interval_strain, "suspension.sample_interval_strain");
  require_positive_sheared(settings.wall_repulsion_range_um, "suspension.wall_repulsion_range_um");
  require_positive_sheared(settings.contact.range_um, "suspension.contact_range_um");
  if (!(settings.averaging_fraction > 0.0 && settings.averaging_fraction <= 1.0)) {
    throw InputError("suspension.averaging_fraction", "must lie in (0, 1]");
  }
}

int whole_spacings(double length_um, double dx_um) {
  return std::max(1, static_cast<int>(std::lround(length_um / dx_um)));
}

// The plane average of u_x over layer y, lattice units.
double layer_velocity_lu(const lattice::FluidSolver& fluid, int y) {
  const auto& grid = fluid.grid();
  const auto& ux = fluid.velocity()[0];
  double sum = 0.0;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) sum += ux[grid.index(x, y, z)];
  }
  return sum / (static_cast<double>(grid.nx()) * grid.nz());
}

// The check of the header: the velocity gradient between the two fluid layers next to each wall
// (nodes 1, 2 and ny - 3, ny - 2), over the imposed rate.
double near_wall_rate_lu(const lattice::FluidSolver& fluid) {
  const int ny = fluid.grid().ny();
  const double bottom = layer_velocity_lu(fluid, 2) - layer_velocity_lu(fluid, 1);
  const double top = layer_velocity_lu(fluid, ny - 2) - layer_velocity_lu(fluid, ny - 3);
  return 0.5 * (bottom + top);
}

class ShearedSuspensionRecorder {
 public:
  // `sample_steps` receives the step of each sample, for the checkpoint (ShearedSuspensionRecord).
  ShearedSuspensionRecorder(ShearedSuspensionRun& run, std::vector<std::size_t>& sample_steps,
                            const ShearedSuspensionSettings& settings, int gap_nodes,
                            double rate_lu)
      : run_(run),
        sample_steps_(sample_steps),
        settings_(settings),
        gap_nodes_(gap_nodes),
        rate_lu_(rate_lu) {}

  void operator()(const coupling::CoupledSimulation& simulation) {
    ShearedSuspensionSample sample;
    sample.time_s = simulation.time_s();
    sample.strain = settings_.shear_rate_per_s * sample.time_s;
    const auto stress = suspension_shear_stress(simulation, gap_nodes_);
    sample.particle_stress_Pa = stress.particle_Pa;
    sample.cytoplasm_stress_Pa = stress.cytoplasm_Pa;
    sample.relative_viscosity =
        1.0 + (stress.particle_Pa + stress.cytoplasm_Pa) / run_.plasma_stress_Pa;
    sample.near_wall_relative_viscosity = near_wall_rate_lu(simulation.fluid()) / rate_lu_;
    sample.contact_pairs = simulation.contact_statistics().pairs_in_range;
    std::vector<std::vector<Vec3>> positions;
    std::vector<std::span<const mesh::Triangle>> triangles;
    for (std::size_t c = 0; c < simulation.cells().size(); ++c) {
      const auto& cell = simulation.cell(c);
      positions.push_back(simulation.positions_now_um(c));
      triangles.emplace_back(cell.model().triangles());
      run_.cell_samples.push_back({sample.time_s, c, simulation.frame().to_um(cell.centroid_lu()),
                                   deformation_index(cell.positions_lu())});
    }
    const auto pierced = find_pierced_cells(
        positions, triangles, contact::PeriodicBox{{run_.length_um, 0.0, run_.width_um}});
    sample.pierced_cells = static_cast<std::size_t>(
        std::ranges::count_if(pierced, [](const auto& other) { return other.has_value(); }));
    if (sample.pierced_cells > 0) ++run_.samples_with_pierced_cells;
    run_.samples.push_back(sample);
    sample_steps_.push_back(simulation.time_step());
  }

 private:
  ShearedSuspensionRun& run_;
  std::vector<std::size_t>& sample_steps_;
  const ShearedSuspensionSettings& settings_;
  int gap_nodes_;
  double rate_lu_;
};

// One sample's and one cell sample's numbers in a fixed order: the layout of the checkpoint and of
// a finished rate's record (sheared_suspension_record).
constexpr std::size_t kShearedSampleValues = 8;
constexpr std::size_t kShearedCellSampleValues = 6;

std::array<double, kShearedSampleValues> sample_values(const ShearedSuspensionSample& s) {
  return {s.time_s,
          s.strain,
          s.relative_viscosity,
          s.particle_stress_Pa,
          s.cytoplasm_stress_Pa,
          s.near_wall_relative_viscosity,
          static_cast<double>(s.contact_pairs),
          static_cast<double>(s.pierced_cells)};
}

std::array<double, kShearedCellSampleValues> cell_sample_values(
    const ShearedSuspensionCellSample& c) {
  return {c.time_s,          static_cast<double>(c.cell), c.centroid_um.x(),
          c.centroid_um.y(), c.centroid_um.z(),           c.deformation_index};
}

// A count read back, refused unless a whole number >= 0 (a cast of anything else is undefined).
std::size_t count_from(double value, const std::string& source, const std::string& what) {
  if (!(value >= 0.0 && value == std::floor(value) && value < 1e18)) {
    throw InputError(source, what + ": not a count");
  }
  return static_cast<std::size_t>(value);
}

ShearedSuspensionSample sample_from(const double* v, const std::string& source,
                                    const std::string& what) {
  return {v[0],
          v[1],
          v[2],
          v[3],
          v[4],
          v[5],
          count_from(v[6], source, what),
          count_from(v[7], source, what)};
}

ShearedSuspensionCellSample cell_sample_from(const double* v, const std::string& source,
                                             const std::string& what) {
  return {v[0], count_from(v[1], source, what), Vec3(v[2], v[3], v[4]), v[5]};
}

// Never stops the run: it carries the samples recorded so far in the checkpoint, so that a resumed
// run reports what a straight one would. As in the tube (suspension_case.cpp, SuspensionRecord),
// the sample of the state an interrupted run reached between two intervals is reported by that
// run but left out of its checkpoint.
class ShearedSuspensionRecord final : public coupling::StopCriterion {
 public:
  ShearedSuspensionRecord(ShearedSuspensionRun& run, std::vector<std::size_t>& sample_steps,
                          std::size_t interval_steps, std::size_t cell_count)
      : run_(run),
        sample_steps_(sample_steps),
        interval_steps_(interval_steps),
        cell_count_(cell_count) {}

  std::optional<std::string> check(const coupling::CoupledSimulation& /*simulation*/) override {
    return std::nullopt;
  }

  void save_state(StateArchive& archive, const std::string& prefix) const override {
    std::vector<double> samples, cells;
    for (std::size_t i = 0; i < run_.samples.size(); ++i) {
      if (sample_steps_[i] % interval_steps_ != 0) continue;
      samples.push_back(static_cast<double>(sample_steps_[i]));
      const auto values = sample_values(run_.samples[i]);
      samples.insert(samples.end(), values.begin(), values.end());
      for (std::size_t c = 0; c < cell_count_; ++c) {
        const auto cell = cell_sample_values(run_.cell_samples[i * cell_count_ + c]);
        cells.insert(cells.end(), cell.begin(), cell.end());
      }
    }
    archive.put(prefix + "samples", std::move(samples));
    archive.put(prefix + "cell_samples", std::move(cells));
  }

  // Each sample is its step, then its values.
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    constexpr std::size_t kStepAndValues = 1 + kShearedSampleValues;
    const auto samples = archive.take(prefix + "samples", std::nullopt);
    if (samples.size() % kStepAndValues != 0) {
      throw InputError(archive.source(), prefix + "samples: not whole samples");
    }
    const std::size_t count = samples.size() / kStepAndValues;
    const auto cells =
        archive.take(prefix + "cell_samples", count * cell_count_ * kShearedCellSampleValues);
    run_.samples.clear();
    run_.cell_samples.clear();
    sample_steps_.clear();
    run_.samples_with_pierced_cells = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const auto* v = samples.data() + i * kStepAndValues;
      sample_steps_.push_back(count_from(v[0], archive.source(), prefix + "samples"));
      run_.samples.push_back(sample_from(v + 1, archive.source(), prefix + "samples"));
      if (run_.samples.back().pierced_cells > 0) ++run_.samples_with_pierced_cells;
    }
    for (std::size_t k = 0; k < count * cell_count_; ++k) {
      run_.cell_samples.push_back(cell_sample_from(cells.data() + k * kShearedCellSampleValues,
                                                   archive.source(), prefix + "cell_samples"));
    }
  }

 private:
  ShearedSuspensionRun& run_;
  std::vector<std::size_t>& sample_steps_;
  std::size_t interval_steps_;
  std::size_t cell_count_;
};

void average_samples(ShearedSuspensionRun& run, double fraction) {
  const double from_strain =
      run.samples.empty() ? 0.0 : run.samples.back().strain * (1.0 - fraction);
  std::vector<double> viscosities;
  double near_wall = 0.0;
  for (const auto& sample : run.samples) {
    if (sample.strain < from_strain || sample.time_s == 0.0) continue;
    viscosities.push_back(sample.relative_viscosity);
    near_wall += sample.near_wall_relative_viscosity;
  }
  run.averaged_samples = viscosities.size();
  if (viscosities.empty()) return;
  const auto spread = spread_of(viscosities);
  run.relative_viscosity = spread.mean;
  run.relative_viscosity_sd = spread.standard_deviation;
  run.near_wall_relative_viscosity = near_wall / static_cast<double>(viscosities.size());
}

}  // namespace

namespace {

// Rows of numbers as JSON arrays (null for a non-finite one).
template <class Rows>
nlohmann::ordered_json rows_json(const Rows& rows) {
  auto json = nlohmann::ordered_json::array();
  for (const auto& row : rows) {
    auto values = nlohmann::ordered_json::array();
    for (const double value : row) values.push_back(number_or_null(value));
    json.push_back(std::move(values));
  }
  return json;
}

// The rows of `key`, each of `width` numbers (null: NaN).
std::vector<std::vector<double>> rows_from(const nlohmann::json& record, const char* key,
                                           std::size_t width, const std::string& source) {
  if (!record.contains(key) || !record.at(key).is_array()) {
    throw InputError(source, std::string("no array \"") + key + "\"");
  }
  std::vector<std::vector<double>> rows;
  for (const auto& row : record.at(key)) {
    if (!row.is_array() || row.size() != width) {
      throw InputError(source, std::string("\"") + key + "\": a row of other than " +
                                   std::to_string(width) + " numbers");
    }
    std::vector<double> values;
    for (const auto& value : row) {
      if (!value.is_null() && !value.is_number()) {
        throw InputError(source, std::string("\"") + key + "\": a value that is not a number");
      }
      values.push_back(value.is_null() ? std::numeric_limits<double>::quiet_NaN()
                                       : value.get<double>());
    }
    rows.push_back(std::move(values));
  }
  return rows;
}

}  // namespace

nlohmann::ordered_json sheared_suspension_record(const ShearedSuspensionRun& run) {
  std::vector<std::array<double, kShearedSampleValues>> samples;
  std::vector<std::array<double, kShearedCellSampleValues>> cells;
  for (const auto& sample : run.samples) samples.push_back(sample_values(sample));
  for (const auto& cell : run.cell_samples) cells.push_back(cell_sample_values(cell));
  return {{"cell_morphologies", run.cell_morphologies},
          {"gap_um", run.gap_um},
          {"length_um", run.length_um},
          {"width_um", run.width_um},
          {"packed_hematocrit", run.packed_hematocrit},
          {"packing_iterations", run.packing_iterations},
          {"plasma_stress_Pa", run.plasma_stress_Pa},
          {"averaged_samples", run.averaged_samples},
          {"relative_viscosity", number_or_null(run.relative_viscosity)},
          {"relative_viscosity_sd", number_or_null(run.relative_viscosity_sd)},
          {"near_wall_relative_viscosity", number_or_null(run.near_wall_relative_viscosity)},
          {"steps", run.steps},
          {"time_s", run.time_s},
          {"close_contact_steps", run.close_contact_steps},
          {"capped_contact_steps", run.capped_contact_steps},
          {"samples_with_pierced_cells", run.samples_with_pierced_cells},
          {"sub_spacing_drag", sub_spacing_drag_json(run.sub_spacing_drag)},
          {"stop_reason", run.stop_reason},
          {"failure", run.failure},
          {"interrupted", run.interrupted},
          {"samples", rows_json(samples)},
          {"cell_samples", rows_json(cells)}};
}

ShearedSuspensionRun sheared_suspension_from_record(const nlohmann::json& record,
                                                    const std::string& source) {
  const auto number = [&](const char* key) { return record_number(record, key, source); };
  const auto count = [&](const char* key) {
    return count_from(number(key), source, std::string("\"") + key + "\"");
  };
  const auto text = [&](const char* key) {
    if (!record.contains(key) || !record.at(key).is_string()) {
      throw InputError(source, std::string("no string \"") + key + "\"");
    }
    return record.at(key).get<std::string>();
  };
  ShearedSuspensionRun run;
  if (!record.contains("cell_morphologies") || !record.at("cell_morphologies").is_array()) {
    throw InputError(source, "no array \"cell_morphologies\"");
  }
  for (const auto& kind : record.at("cell_morphologies")) {
    if (!kind.is_number_unsigned()) {
      throw InputError(source, "\"cell_morphologies\": not a morphology index");
    }
    run.cell_morphologies.push_back(kind.get<std::size_t>());
  }
  run.gap_um = number("gap_um");
  run.length_um = number("length_um");
  run.width_um = number("width_um");
  run.packed_hematocrit = number("packed_hematocrit");
  run.packing_iterations = count("packing_iterations");
  run.plasma_stress_Pa = number("plasma_stress_Pa");
  run.averaged_samples = count("averaged_samples");
  run.relative_viscosity = number("relative_viscosity");
  run.relative_viscosity_sd = number("relative_viscosity_sd");
  run.near_wall_relative_viscosity = number("near_wall_relative_viscosity");
  run.steps = count("steps");
  run.time_s = number("time_s");
  run.close_contact_steps = count("close_contact_steps");
  run.capped_contact_steps = count("capped_contact_steps");
  run.samples_with_pierced_cells = count("samples_with_pierced_cells");
  run.sub_spacing_drag =
      sub_spacing_drag_from_json(record.value("sub_spacing_drag", nullptr), source);
  run.stop_reason = text("stop_reason");
  run.failure = text("failure");
  run.interrupted = record.value("interrupted", false);
  for (const auto& v : rows_from(record, "samples", kShearedSampleValues, source)) {
    run.samples.push_back(sample_from(v.data(), source, "\"samples\""));
  }
  for (const auto& v : rows_from(record, "cell_samples", kShearedCellSampleValues, source)) {
    run.cell_samples.push_back(cell_sample_from(v.data(), source, "\"cell_samples\""));
  }
  return run;
}

SuspensionShearStress suspension_shear_stress(const coupling::CoupledSimulation& simulation,
                                              int gap_nodes) {
  const auto& fluid = simulation.fluid();
  const auto& grid = fluid.grid();
  const double dx_um = simulation.frame().dx_um;
  const double volume_um3 =
      static_cast<double>(grid.nx()) * gap_nodes * grid.nz() * dx_um * dx_um * dx_um;
  SuspensionShearStress stress;
  // sigma_p: pN um / um^3 = pN / um^2 = Pa. Summed cell after cell, vertex after vertex.
  double moment_pN_um = 0.0;
  for (const auto& cell : simulation.cells()) {
    const auto positions = cell.positions_um();
    const auto forces = cell.total_forces_pN();
    const auto& terms = cell.membrane_forces().terms;
    const auto friction = std::find_if(terms.begin(), terms.end(),
                                       [](const auto& term) { return term.name == "viscosity"; });
    const bool with_friction =
        friction != terms.end() && friction->forces_pN.size() == positions.size();
    for (std::size_t v = 0; v < positions.size(); ++v) {
      double force_x = forces[v].x();
      // The friction went into the fluid implicitly, not through the spread forces.
      if (with_friction) force_x += friction->forces_pN[v].x();
      moment_pN_um += positions[v].y() * force_x;
    }
  }
  stress.particle_Pa = -moment_pN_um / volume_um3;
  if (!fluid.has_viscosity_contrast()) return stress;
  // mu_delta: (nu_k - nu_0) (du_x/dy + du_y/dx) over the nodes of a class other than 0, by central
  // differences (the cells keep off the walls, so every such node has fluid neighbours in y).
  const auto classes = fluid.viscosity_classes();
  const auto rates = fluid.class_rates();
  const auto viscosity_lu = [](const lattice::RelaxationRates& r) {
    return (1.0 / r.even - 0.5) * lattice::kSoundSpeedSquared;
  };
  const double outer_lu = viscosity_lu(rates[0]);
  const auto& u = fluid.velocity();
  const int nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
  double sum_lu = 0.0;
  for (int z = 0; z < nz; ++z) {
    for (int y = 1; y < ny - 1; ++y) {
      for (int x = 0; x < nx; ++x) {
        const auto node = grid.index(x, y, z);
        if (classes[node] == 0) continue;
        const double dux_dy = 0.5 * (u[0][grid.index(x, y + 1, z)] - u[0][grid.index(x, y - 1, z)]);
        const double duy_dx = 0.5 * (u[1][grid.index((x + 1) % nx, y, z)] -
                                     u[1][grid.index((x + nx - 1) % nx, y, z)]);
        sum_lu += (viscosity_lu(rates[classes[node]]) - outer_lu) * (dux_dy + duy_dx);
      }
    }
  }
  // Lattice stress (density 1) per node over the gap's nodes, in Pa.
  const double nodes = static_cast<double>(nx) * gap_nodes * nz;
  stress.cytoplasm_Pa = simulation.units().to_physical(PhysicalUnit::pressure_Pa, sum_lu / nodes);
  return stress;
}

ShearedSuspensionRun run_sheared_suspension(std::span<const SuspensionMorphology> morphologies,
                                            std::span<const std::size_t> cell_morphologies,
                                            const SuspensionPhysics& physics,
                                            const ShearedSuspensionSettings& settings,
                                            const SuspensionConfigure& configure) {
  validate_sheared(settings);
  require_contact_reaches_across_edges(morphologies, settings.contact.range_um);
  require_growth_before_window(
      settings.packing.scale, settings.growth_time_s,
      (1.0 - settings.averaging_fraction) * settings.strain / settings.shear_rate_per_s,
      "suspension.strain");
  const double dx_um = physics.units.dx_m() * 1e6;
  ShearBox box;
  box.wall_layers = 1;
  box.nx = whole_spacings(settings.length_um, dx_um);
  box.nz = whole_spacings(settings.width_um, dx_um);
  box.ny = whole_spacings(settings.gap_um, dx_um) + 2 * box.wall_layers;

  ShearedSuspensionRun run;
  run.cell_morphologies.assign(cell_morphologies.begin(), cell_morphologies.end());
  run.gap_um = box.gap_nodes() * dx_um;
  run.length_um = box.nx * dx_um;
  run.width_um = box.nz * dx_um;
  physics.units.check_lattice_velocity(0.5 * settings.shear_rate_per_s * run.gap_um * 1e-6,
                                       "shear.rates_per_s (the walls' speed, rate x gap / 2)");

  std::vector<mesh::TriangleMesh> meshes;
  for (const auto& morphology : morphologies) meshes.push_back(morphology.mesh);
  const PackingSlab slab{run.gap_um, run.length_um, run.width_um};
  const Packing packing =
      settings.placed_cells.empty()
          ? pack_cells(meshes, cell_morphologies, slab, settings.packing)
          : place_cells(meshes, cell_morphologies, settings.placed_cells, slab, settings.packing);
  run.packed_hematocrit = packing.hematocrit;
  run.packing_iterations = packing.iterations;

  const double rate_lu =
      physics.units.to_lattice(PhysicalUnit::shear_rate_per_s, settings.shear_rate_per_s);
  run.plasma_stress_Pa = physics.units.to_physical(
      PhysicalUnit::pressure_Pa, physics.units.lattice_kinematic_viscosity() * rate_lu);
  const Vec3 origin_um = -0.5 * dx_um * Vec3(box.nx - 1, box.ny - 1, box.nz - 1);
  coupling::CoupledSimulation simulation(shear_fluid(box, physics.fluid, "walls", rate_lu),
                                         physics.units, physics.coupling, origin_um);
  if (packing.scale < 1.0) {
    simulation.grow_cells(cell_growth_for(physics.units, packing.scale, settings.growth_time_s));
  }
  for (std::size_t c = 0; c < cell_morphologies.size(); ++c) {
    const auto& morphology = morphologies[cell_morphologies[c]];
    simulation.add_cell(membrane::MembraneModel(morphology.mesh, morphology.membrane),
                        packing.positions_um[c]);
  }
  const double half_gap_um = 0.5 * run.gap_um;
  add_suspension_walls(
      simulation, morphologies, cell_morphologies,
      {settings.wall_repulsion_pN_per_um2, settings.wall_repulsion_range_um, settings.wall_law},
      [half_gap_um](const Vec3& position) { return slab_wall_distance(position, half_gap_um); });
  simulation.set_cell_contact(settings.contact, "suspension.contact_force_pN");
  const double interval_s = settings.sample_interval_strain / settings.shear_rate_per_s;
  const auto interval_steps = std::max<std::size_t>(
      1, static_cast<std::size_t>(
             std::round(physics.units.to_lattice(PhysicalUnit::time_s, interval_s))));
  std::vector<std::size_t> sampled_at_steps;
  coupling::Observer recorder{
      "sheared_suspension_samples", interval_steps,
      ShearedSuspensionRecorder(run, sampled_at_steps, settings, box.gap_nodes(), rate_lu)};
  recorder.needs_term_forces = true;  // the membrane viscosity's friction, for sigma_p
  recorder.reads_fluid = true;        // the velocity next to the walls
  simulation.add_observer(std::move(recorder));
  simulation.add_stop_criterion(
      coupling::stop_at_time(settings.strain / settings.shear_rate_per_s));
  simulation.add_stop_criterion(std::make_unique<ShearedSuspensionRecord>(
      run, sampled_at_steps, interval_steps, cell_morphologies.size()));
  if (configure) configure(simulation);
  const auto end = run_to_end(simulation);
  run.stop_reason = end.stop_reason;
  run.failure = end.failure;
  run.interrupted = end.interrupted;
  run.steps = simulation.time_step();
  run.time_s = simulation.time_s();
  run.close_contact_steps = simulation.close_contact_steps();
  run.capped_contact_steps = simulation.capped_contact_steps();
  run.sub_spacing_drag = simulation.sub_spacing_drag_summary();
  average_samples(run, settings.averaging_fraction);
  return run;
}

}  // namespace rbcsim::cases
