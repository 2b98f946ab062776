#include "cases/sheared_suspension.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "cases/capillary_observables.hpp"
#include "cases/release_orientations.hpp"
#include "cases/shear_case.hpp"
#include "cases/wall_repulsion.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
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
  ShearedSuspensionRecorder(ShearedSuspensionRun& run, const ShearedSuspensionSettings& settings,
                            int gap_nodes, double rate_lu)
      : run_(run), settings_(settings), gap_nodes_(gap_nodes), rate_lu_(rate_lu) {}

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
  }

 private:
  ShearedSuspensionRun& run_;
  const ShearedSuspensionSettings& settings_;
  int gap_nodes_;
  double rate_lu_;
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
  for (std::size_t c = 0; c < cell_morphologies.size(); ++c) {
    const auto& morphology = morphologies[cell_morphologies[c]];
    simulation.add_cell(membrane::MembraneModel(morphology.mesh, morphology.membrane),
                        packing.positions_um[c]);
  }
  const double half_gap_um = 0.5 * run.gap_um;
  add_suspension_walls(
      simulation, morphologies, cell_morphologies,
      {settings.wall_repulsion_pN_per_um2, settings.wall_repulsion_range_um},
      [half_gap_um](const Vec3& position) { return slab_wall_distance(position, half_gap_um); });
  simulation.set_cell_contact(settings.contact, "suspension.contact_force_pN");
  const double interval_s = settings.sample_interval_strain / settings.shear_rate_per_s;
  const auto interval_steps = std::max<std::size_t>(
      1, static_cast<std::size_t>(
             std::round(physics.units.to_lattice(PhysicalUnit::time_s, interval_s))));
  coupling::Observer recorder{"sheared_suspension_samples", interval_steps,
                              ShearedSuspensionRecorder(run, settings, box.gap_nodes(), rate_lu)};
  recorder.needs_term_forces = true;  // the membrane viscosity's friction, for sigma_p
  simulation.add_observer(std::move(recorder));
  simulation.add_stop_criterion(
      coupling::stop_at_time(settings.strain / settings.shear_rate_per_s));
  if (configure) configure(simulation);
  const auto end = run_to_end(simulation);
  run.stop_reason = end.stop_reason;
  run.failure = end.failure;
  run.interrupted = end.interrupted;
  run.steps = simulation.time_step();
  run.time_s = simulation.time_s();
  run.close_contact_steps = simulation.close_contact_steps();
  run.capped_contact_steps = simulation.capped_contact_steps();
  average_samples(run, settings.averaging_fraction);
  return run;
}

}  // namespace rbcsim::cases
