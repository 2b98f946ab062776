#include "cases/capillary_case.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "cases/capillary_flow.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/registry.hpp"
#include "geometry/wall_measures.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/geometry.hpp"
#include "mesh/transform.hpp"
#include "parallel/distributed_fluid.hpp"

namespace rbcsim::cases {
namespace {

using units::PhysicalUnit;

// Where the mesh's z axis (a built-in shape's symmetry axis) is turned, by name.
struct CellAxis {
  std::string_view name;
  Eigen::Vector3d rotation_axis;  // the rotation that takes z onto this axis
  double angle_rad;
};

// The signed axes matter for a shape without mirror symmetry: the stomatocyte's cup opens towards
// +z, so "x" opens it downstream and "-x" upstream, as the parachute a cell becomes in a tube.
const std::array kCellAxes{
    CellAxis{"z", Eigen::Vector3d::UnitZ(), 0.0},
    CellAxis{"x", Eigen::Vector3d::UnitY(), 0.5 * std::numbers::pi},    // z -> x
    CellAxis{"y", Eigen::Vector3d::UnitX(), -0.5 * std::numbers::pi},   // z -> y
    CellAxis{"-z", Eigen::Vector3d::UnitX(), std::numbers::pi},         // z -> -z
    CellAxis{"-x", Eigen::Vector3d::UnitY(), -0.5 * std::numbers::pi},  // z -> -x
    CellAxis{"-y", Eigen::Vector3d::UnitX(), 0.5 * std::numbers::pi},   // z -> -y
};

void require_positive(double value, const char* option) {
  if (!(value > 0.0)) throw InputError(option, "must be > 0");
}

void validate(const CapillarySettings& settings) {
  require_positive(settings.mean_inlet_velocity_m_per_s, "capillary.inlet_velocity_m_per_s");
  require_positive(settings.release_gap_um, "capillary.release_gap_um");
  require_positive(settings.pass_margin_um, "capillary.pass_margin_um");
  require_positive(settings.max_time_s, "capillary.max_time_s");
  require_positive(settings.sample_interval_s, "capillary.sample_interval_s");
  require_positive(settings.wall_repulsion_range_um, "capillary.wall_repulsion_range_um");
}

// The wall repulsion as an external force; each vertex's force at contact is the pressure times
// the membrane area per vertex.
void add_repulsion(coupling::CoupledSimulation& simulation, const geometry::WallShape& wall,
                   const mesh::TriangleMesh& cell, const CapillarySettings& settings) {
  if (settings.wall_repulsion_pN_per_um2 == 0.0) return;
  if (!wall.radius_at_um(0.0)) {
    throw InputError("capillary.wall_repulsion_pN_per_um2",
                     "the wall repulsion needs a circular tube (a built-in capillary); set it to 0 "
                     "for a wall file");
  }
  const WallRepulsion repulsion{settings.wall_repulsion_pN_per_um2 * mesh::surface_area_um2(cell) /
                                    static_cast<double>(cell.vertex_count()),
                                settings.wall_repulsion_range_um};
  simulation.add_external_force(
      [&wall, repulsion](std::size_t, const coupling::Cell& state, std::span<Vec3> forces_pN) {
        add_tube_wall_repulsion(
            state.positions_um(), [&wall](double x_um) { return *wall.radius_at_um(x_um); },
            repulsion, forces_pN);
      });
}

// The oriented cell with its upstream end release_gap_um past the inlet plane, centred in y and z
// on the lumen's box.
mesh::TriangleMesh released_cell(const mesh::TriangleMesh& cell_mesh,
                                 const geometry::WallShape& wall, const CapillaryLattice& lattice,
                                 const CapillarySettings& settings) {
  auto cell = oriented_cell(cell_mesh, settings.cell_axis);
  const auto bounds = wall.fluid_bounds();
  const Vec3 centroid = mesh::solid_centroid_um(cell);
  double min_x_um = centroid.x();
  for (const auto& position : cell.positions_um) min_x_um = std::min(min_x_um, position.x());
  const Vec3 target(lattice.inlet_x_um + settings.release_gap_um + (centroid.x() - min_x_um),
                    0.5 * (bounds.min_um.y() + bounds.max_um.y()),
                    0.5 * (bounds.min_um.z() + bounds.max_um.z()));
  for (auto& position : cell.positions_um) position += target - centroid;
  return cell;
}

// The cell must start inside the lumen: every vertex's nearest node a fluid node of the lumen
// slices. Checked before the fluid is settled, so that bad input fails at once (add_cell checks
// again, with the solver's own mask).
void require_cell_in_lumen(const mesh::TriangleMesh& cell, const CapillaryLattice& lattice) {
  const auto& grid = lattice.grid_um;
  for (std::size_t v = 0; v < cell.vertex_count(); ++v) {
    const Vec3 node = ((cell.positions_um[v] - grid.origin_um) / grid.dx_um).array().round();
    const bool in_lumen =
        node.x() >= 1 && node.x() <= grid.nx - 2 && node.y() >= 0 && node.y() < grid.ny &&
        node.z() >= 0 && node.z() < grid.nz &&
        lattice.solid_mask[grid.index(static_cast<int>(node.x()), static_cast<int>(node.y()),
                                      static_cast<int>(node.z()))] == geometry::kFluid;
    if (!in_lumen) {
      throw InputError("capillary.release_gap_um",
                       "the released cell does not fit in the lumen (vertex " + std::to_string(v) +
                           " at x = " + format_number(cell.positions_um[v].x()) +
                           " um is in the wall)");
    }
  }
}

// The largest lattice velocity to expect: the Poiseuille peak (twice the mean) in the narrowest
// slice, where the mean is the inlet's times the area ratio. Throws InputError beyond the Mach
// limit of the unit converter.
void check_peak_velocity(const CapillaryLattice& lattice, const units::UnitConverter& units,
                         double mean_velocity_m_per_s) {
  const auto& grid = lattice.grid_um;
  double narrowest_um2 = geometry::slice_fluid_area_um2(lattice.solid_mask, grid, 1);
  for (int i = 2; i < grid.nx - 1; ++i) {
    narrowest_um2 =
        std::min(narrowest_um2, geometry::slice_fluid_area_um2(lattice.solid_mask, grid, i));
  }
  const double inlet_um2 = geometry::slice_fluid_area_um2(lattice.solid_mask, grid, 0);
  units.check_lattice_velocity(2.0 * mean_velocity_m_per_s * inlet_um2 / narrowest_um2,
                               "capillary.inlet_velocity_m_per_s (peak velocity in the throat)");
}

double mean_edge_length_um(const membrane::MembraneModel& model) {
  const auto& lengths = model.reference().edge_lengths_um;
  double sum = 0.0;
  for (const double length : lengths) sum += length;
  return sum / static_cast<double>(lengths.size());
}

CapillaryFlowNumbers flow_numbers(const CapillaryPhysics& physics,
                                  const CapillarySettings& settings, double inlet_diameter,
                                  const membrane::MembraneModel& model) {
  CapillaryFlowNumbers numbers;
  numbers.mean_inlet_velocity_m_per_s = settings.mean_inlet_velocity_m_per_s;
  numbers.inlet_diameter_um = inlet_diameter;
  numbers.reynolds_number = reynolds_number(settings.mean_inlet_velocity_m_per_s, inlet_diameter,
                                            physics.kinematic_viscosity_m2_per_s);
  const auto& membrane = physics.membrane;
  numbers.shear_modulus_N_per_m =
      link_shear_modulus_N_per_m(membrane.k_link_kBT, membrane.tau_link, physics.thermal_energy_J,
                                 membrane.persistence_length_um, mean_edge_length_um(model));
  numbers.capillary_number =
      capillary_number(settings.mean_inlet_velocity_m_per_s,
                       physics.density_kg_per_m3 * physics.kinematic_viscosity_m2_per_s,
                       numbers.shear_modulus_N_per_m);
  return numbers;
}

class StopWhen final : public coupling::StopCriterion {
 public:
  using Test = std::function<std::optional<std::string>(const coupling::CoupledSimulation&)>;
  explicit StopWhen(Test test) : test_(std::move(test)) {}
  std::optional<std::string> check(const coupling::CoupledSimulation& simulation) override {
    return test_(simulation);
  }

 private:
  Test test_;
};

Vec3 centroid_um(const coupling::CoupledSimulation& simulation) {
  return simulation.frame().to_um(simulation.cell(0).centroid_lu());
}

CapillarySample sample_of(const coupling::CoupledSimulation& simulation) {
  const auto& cell = simulation.cell(0);
  CapillarySample sample;
  sample.time_s = simulation.time_s();
  sample.centroid_um = centroid_um(simulation);
  sample.velocity_x_m_per_s = simulation.units().to_physical(
      PhysicalUnit::velocity_m_per_s, mean_velocity(cell.velocities_lu()).x());
  sample.deformation_index = deformation_index(cell.positions_lu());
  sample.extents_um = simulation.frame().dx_um * vertex_extents(cell.positions_lu());
  sample.area_strain = mesh::area_strain(simulation.positions_now_um(0), cell.model().triangles(),
                                         cell.model().reference().triangle_areas_um2);
  return sample;
}

// The narrow section's crossings of the cell's centroid, front (largest vertex x) and rear
// (smallest vertex x).
struct CellTransits {
  NarrowSectionTransit centroid;
  NarrowSectionTransit front;
  NarrowSectionTransit rear;
  CellTransits(double start_um, double end_um)
      : centroid(start_um, end_um), front(start_um, end_um), rear(start_um, end_um) {}
  void save_state(StateArchive& archive, const std::string& prefix) const {
    centroid.save_state(archive, prefix + "transit.");
    front.save_state(archive, prefix + "front_transit.");
    rear.save_state(archive, prefix + "rear_transit.");
  }
  void restore_state(StateArchive& archive, const std::string& prefix) {
    centroid.restore_state(archive, prefix + "transit.");
    front.restore_state(archive, prefix + "front_transit.");
    rear.restore_state(archive, prefix + "rear_transit.");
  }
};

void copy_transit(const CellTransits& transits, CapillaryRun& run) {
  run.entry_time_s = transits.centroid.entry_time_s();
  run.exit_time_s = transits.centroid.exit_time_s();
  run.transit_time_s = transits.centroid.transit_time_s();
  run.passed = transits.centroid.passed();
  run.front_entry_time_s = transits.front.entry_time_s();
  run.rear_exit_time_s = transits.rear.exit_time_s();
  run.whole_cell_transit_time_s.reset();
  if (run.front_entry_time_s && run.rear_exit_time_s) {
    run.whole_cell_transit_time_s = *run.rear_exit_time_s - *run.front_entry_time_s;
  }
}

// Follows the transit and the peak deformation every step.
class TransitRecorder {
 public:
  TransitRecorder(CapillaryRun& run, CellTransits& transit) : run_(run), transit_(transit) {}

  void operator()(const coupling::CoupledSimulation& simulation) {
    const double time_s = simulation.time_s();
    const double centroid_x_um = centroid_um(simulation).x();
    const double index = deformation_index(simulation.cell(0).positions_lu());
    transit_.centroid.add_sample(time_s, centroid_x_um);
    double front_lu = -INFINITY;
    double rear_lu = INFINITY;
    for (const auto& position : simulation.cell(0).positions_lu()) {
      front_lu = std::max(front_lu, position.x());
      rear_lu = std::min(rear_lu, position.x());
    }
    const auto& frame = simulation.frame();
    transit_.front.add_sample(time_s, frame.origin_um.x() + frame.dx_um * front_lu);
    transit_.rear.add_sample(time_s, frame.origin_um.x() + frame.dx_um * rear_lu);
    if (simulation.time_step() == 0) run_.initial_deformation_index = index;
    if (index > run_.peak_deformation_index) {
      run_.peak_deformation_index = index;
      run_.peak_time_s = time_s;
      run_.peak_centroid_x_um = centroid_x_um;
    }
    run_.final_deformation_index = index;
    run_.final_centroid_x_um = centroid_x_um;
    copy_transit(transit_, run_);
  }

 private:
  CapillaryRun& run_;
  CellTransits& transit_;
};

// The samples taken so far and the steps they were taken at.
struct SampleLog {
  std::vector<CapillarySample>& samples;
  std::vector<std::size_t> steps;
};

// Per sample in a checkpoint: its step and its eleven numbers.
constexpr std::size_t kSampleValues = 12;

// The samples taken on their interval, as an array of kSampleValues numbers per sample. An
// interrupted run's observers also see the state reached between two intervals; that sample is
// reported but left out of the checkpoint, which a straight run would not have.
std::vector<double> flattened(const SampleLog& log, std::size_t interval_steps) {
  std::vector<double> values;
  for (std::size_t i = 0; i < log.samples.size(); ++i) {
    if (log.steps[i] % interval_steps != 0) continue;
    const auto& sample = log.samples[i];
    values.insert(values.end(),
                  {static_cast<double>(log.steps[i]), sample.time_s, sample.centroid_um.x(),
                   sample.centroid_um.y(), sample.centroid_um.z(), sample.velocity_x_m_per_s,
                   sample.deformation_index, sample.extents_um.x(), sample.extents_um.y(),
                   sample.extents_um.z(), sample.area_strain.total_relative_change,
                   sample.area_strain.max_abs_triangle_deviation});
  }
  return values;
}

void restore_samples(SampleLog& log, const std::vector<double>& values) {
  log.samples.clear();
  log.steps.clear();
  for (std::size_t i = 0; i + kSampleValues <= values.size(); i += kSampleValues) {
    const auto* v = values.data() + i;
    log.steps.push_back(static_cast<std::size_t>(v[0]));
    log.samples.push_back(
        {v[1], Vec3(v[2], v[3], v[4]), v[5], v[6], Vec3(v[7], v[8], v[9]), {v[10], v[11]}});
  }
}

// Never stops the run: it carries what the observers recorded so far (the samples, the transit,
// the peak deformation) in the checkpoint, so a resumed run reports what a straight one would.
class RecordInCheckpoint final : public coupling::StopCriterion {
 public:
  RecordInCheckpoint(CapillaryRun& run, CellTransits& transit, SampleLog& log,
                     std::size_t sample_interval_steps)
      : run_(run), transit_(transit), log_(log), sample_interval_steps_(sample_interval_steps) {}
  std::optional<std::string> check(const coupling::CoupledSimulation& /*simulation*/) override {
    return std::nullopt;
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put(prefix + "samples", flattened(log_, sample_interval_steps_));
    archive.put(prefix + "deformation",
                {run_.initial_deformation_index, run_.peak_deformation_index, run_.peak_time_s,
                 run_.peak_centroid_x_um, run_.final_deformation_index, run_.final_centroid_x_um});
    transit_.save_state(archive, prefix);
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    const auto samples = archive.take(prefix + "samples", std::nullopt);
    if (samples.size() % kSampleValues != 0) {
      throw InputError(archive.source(), prefix + "samples: not whole samples");
    }
    restore_samples(log_, samples);
    const auto deformation = archive.take(prefix + "deformation", 6);
    run_.initial_deformation_index = deformation[0];
    run_.peak_deformation_index = deformation[1];
    run_.peak_time_s = deformation[2];
    run_.peak_centroid_x_um = deformation[3];
    run_.final_deformation_index = deformation[4];
    run_.final_centroid_x_um = deformation[5];
    transit_.restore_state(archive, prefix);
    copy_transit(transit_, run_);
  }

 private:
  CapillaryRun& run_;
  CellTransits& transit_;
  SampleLog& log_;
  std::size_t sample_interval_steps_;
};

void add_stop_criteria(coupling::CoupledSimulation& simulation, const CapillaryRun& run,
                       const CapillaryLattice& lattice, const CapillarySettings& settings) {
  const double passed_x_um = run.narrow_end_um + settings.pass_margin_um;
  // Passed: the centroid beyond the margin and the whole cell out of the narrow section (so that
  // the last vertex's exit, the whole-cell transit, is recorded too).
  const double rear_out_lu =
      (run.narrow_end_um - lattice.grid_um.origin_um.x()) / lattice.grid_um.dx_um;
  simulation.add_stop_criterion(std::make_unique<StopWhen>(
      [passed_x_um,
       rear_out_lu](const coupling::CoupledSimulation& s) -> std::optional<std::string> {
        if (centroid_um(s).x() < passed_x_um) return std::nullopt;
        for (const auto& position : s.cell(0).positions_lu()) {
          if (position.x() <= rear_out_lu) return std::nullopt;
        }
        return "the centroid passed x = " + format_significant(passed_x_um, 6) +
               " um and the whole cell left the narrow section";
      }));
  const double guard_lu =
      (lattice.outlet_x_um - lattice.grid_um.origin_um.x()) / lattice.grid_um.dx_um -
      kOutletGuardDx;
  simulation.add_stop_criterion(std::make_unique<StopWhen>(
      [guard_lu](const coupling::CoupledSimulation& s) -> std::optional<std::string> {
        for (const auto& position : s.cell(0).positions_lu()) {
          if (position.x() >= guard_lu) return "the cell reached the outlet";
        }
        return std::nullopt;
      }));
  simulation.add_stop_criterion(coupling::stop_at_time(settings.max_time_s));
}

std::size_t sample_interval_steps(const units::UnitConverter& units, double interval_s) {
  const double steps = std::round(units.to_lattice(PhysicalUnit::time_s, interval_s));
  return std::max<std::size_t>(1, static_cast<std::size_t>(steps));
}

std::string not_passed_reason(const CapillaryRun& run) {
  return "the cell did not pass the narrow section (centroid at x = " +
         format_number(run.final_centroid_x_um) + " um, narrow section ends at " +
         format_number(run.narrow_end_um) + " um): " + run.stop_reason;
}

// Runs the fluid alone to its steady state (across the run's processes, in slabs); false if it
// did not get there.
bool settle_fluid(lattice::FluidSolver& fluid, const coupling::CouplingParameters& coupling,
                  const CapillarySettings& settings, CapillaryRun& run) {
  const auto steady = parallel::run_to_steady_state(
      coupling.processes, fluid, coupling.block_planes,
      {settings.fluid_tolerance, settings.fluid_check_interval_steps, settings.fluid_max_steps});
  run.fluid_settling_steps = steady.steps;
  if (steady.converged) return true;
  run.failure = "the fluid did not reach its steady state in " + std::to_string(steady.steps) +
                " steps (relative velocity change " +
                format_number(steady.relative_velocity_change) + " per check)";
  return false;
}

}  // namespace

std::vector<std::string> cell_axis_names() {
  return entry_names(std::span<const CellAxis>(kCellAxes));
}

mesh::TriangleMesh oriented_cell(mesh::TriangleMesh mesh, std::string_view cell_axis) {
  const auto& axis =
      find_entry(std::span<const CellAxis>(kCellAxes), cell_axis, "capillary.cell_axis");
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(axis.angle_rad, axis.rotation_axis).matrix();
  for (auto& position : mesh.positions_um) position = rotation * position;
  return mesh;
}

CapillaryRun run_capillary(const mesh::TriangleMesh& cell_mesh, const CapillaryPhysics& physics,
                           const CapillarySettings& settings, const CapillaryConfigure& configure) {
  validate(settings);
  const auto lattice = capillary_lattice(physics.wall, physics.units.dx_m() * 1e6);
  check_peak_velocity(lattice, physics.units, settings.mean_inlet_velocity_m_per_s);
  const auto cell = released_cell(cell_mesh, physics.wall, lattice, settings);
  require_cell_in_lumen(cell, lattice);
  membrane::MembraneModel model(cell, physics.membrane);

  CapillaryRun run;
  std::tie(run.narrow_start_um, run.narrow_end_um) =
      narrow_section_um(physics.wall, lattice, physics.wall_source);
  run.numbers = flow_numbers(physics, settings, inlet_diameter_um(physics.wall, lattice), model);
  run.throat_diameter_um =
      throat_diameter_um(physics.wall, lattice, run.narrow_start_um, run.narrow_end_um);
  run.cell_diameter_um = vertex_extents(cell_mesh.positions_um).maxCoeff();

  auto fluid = capillary_fluid(physics.wall, lattice, physics.fluid,
                               physics.units.to_lattice(PhysicalUnit::velocity_m_per_s,
                                                        settings.mean_inlet_velocity_m_per_s));
  try {
    if (!settle_fluid(*fluid, physics.coupling, settings, run)) return run;
  } catch (const RuntimeFailure& failure) {
    run.stop_reason = run.failure = std::string("fluid alone: ") + failure.what();
    return run;
  }
  coupling::CoupledSimulation simulation(std::move(fluid), physics.units, physics.coupling,
                                         lattice.grid_um.origin_um);
  simulation.add_cell(std::move(model), cell.positions_um);
  add_repulsion(simulation, physics.wall, cell, settings);
  CellTransits transit(run.narrow_start_um, run.narrow_end_um);
  simulation.add_observer({"capillary_transit", 1, TransitRecorder(run, transit)});
  const auto interval_steps = sample_interval_steps(physics.units, settings.sample_interval_s);
  SampleLog log{run.samples, {}};
  simulation.add_observer(
      {"capillary_samples", interval_steps, [&log](const coupling::CoupledSimulation& s) {
         log.samples.push_back(sample_of(s));
         log.steps.push_back(s.time_step());
       }});
  add_stop_criteria(simulation, run, lattice, settings);
  simulation.add_stop_criterion(
      std::make_unique<RecordInCheckpoint>(run, transit, log, interval_steps));
  if (configure) configure(simulation);
  // Steps and capped steps from the simulation's counters (restored on resume), not from this
  // run() call's summary.
  const auto record_end = [&run, &simulation] {
    run.steps = simulation.time_step();
    run.time_s = simulation.time_s();
    run.force_capped_steps = simulation.capped_steps_per_cell().at(0);
    run.phase_times = simulation.phase_times();
    run.sub_spacing_drag = simulation.sub_spacing_drag_summary();
  };
  try {
    run.stop_reason = simulation.run().stop_reason;
    record_end();
  } catch (const Interrupted& interrupted) {
    record_end();
    run.interrupted = true;
    run.stop_reason = run.failure = interrupted.what();
    return run;
  } catch (const RuntimeFailure& failure) {
    record_end();
    // The run stopped at the failure: say so where the stop reason is read (the summary line).
    run.stop_reason = run.failure = failure.what();
    return run;
  }
  if (!run.passed) run.failure = not_passed_reason(run);
  return run;
}

}  // namespace rbcsim::cases
