#include "cases/suspension_case.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>

#include "cases/capillary_observables.hpp"
#include "cases/release_orientations.hpp"
#include "cases/suspension_packing.hpp"
#include "cases/suspension_profile.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/state_archive.hpp"
#include "common/track_change.hpp"
#include "geometry/lattice_grid.hpp"
#include "geometry/tube_wall.hpp"
#include "geometry/voxelise.hpp"
#include "geometry/wall_links.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/geometry.hpp"
#include "parallel/distributed_fluid.hpp"

namespace rbcsim::cases {
namespace {

using units::PhysicalUnit;

// The cell-free layer's bins: about this long along the axis and along the circumference.
constexpr double kLayerBinUm = 2.0;

void require_positive_setting(double value, const char* option) {
  if (!(value > 0.0)) throw InputError(option, "must be > 0");
}

void validate(const SuspensionSettings& settings) {
  require_positive_setting(settings.tube_diameter_um, "suspension.tube_diameter_um");
  require_positive_setting(settings.tube_length_um, "suspension.tube_length_um");
  require_positive_setting(settings.plasma_mean_velocity_m_per_s,
                           "suspension.plasma_mean_velocity_m_per_s");
  require_positive_setting(settings.duration_s, "suspension.duration_s");
  require_positive_setting(settings.sample_interval_s, "suspension.sample_interval_s");
  require_positive_setting(settings.wall_repulsion_range_um, "suspension.wall_repulsion_range_um");
  require_positive_setting(settings.contact.range_um, "suspension.contact_range_um");
  if (!(settings.averaging_fraction > 0.0 && settings.averaging_fraction <= 1.0)) {
    throw InputError("suspension.averaging_fraction", "must lie in (0, 1]");
  }
  require_growth_before_window(settings.packing.scale, settings.growth_time_s,
                               settings.duration_s * (1.0 - settings.averaging_fraction),
                               "suspension.duration_s");
}

}  // namespace

void require_growth_before_window(double packing_scale, double growth_time_s, double window_start_s,
                                  const char* length_option) {
  if (packing_scale >= 1.0) return;
  require_positive_setting(growth_time_s, "suspension.growth_time_s");
  if (growth_time_s > window_start_s) {
    throw InputError("suspension.growth_time_s",
                     format_number(growth_time_s) +
                         " s: the cells packed at suspension.packing_scale " +
                         format_number(packing_scale) +
                         " would still be growing when the averaging window starts (" +
                         format_number(window_start_s) + " s); shorten the growth, lengthen " +
                         length_option + " or lower suspension.averaging_fraction");
  }
}

coupling::CellGrowth cell_growth_for(const units::UnitConverter& units, double packing_scale,
                                     double growth_time_s) {
  if (packing_scale >= 1.0) return {};
  const double steps = std::round(units.to_lattice(PhysicalUnit::time_s, growth_time_s));
  return {packing_scale, std::max<std::size_t>(1, static_cast<std::size_t>(steps))};
}

void require_contact_reaches_across_edges(std::span<const SuspensionMorphology> morphologies,
                                          double range_um) {
  for (const auto& morphology : morphologies) {
    const membrane::MembraneModel probe(morphology.mesh, morphology.membrane);
    double longest_um = 0.0;
    for (const double length : probe.reference().edge_lengths_um) {
      longest_um = std::max(longest_um, length);
    }
    if (range_um < longest_um) {
      throw InputError("suspension.contact_range_um",
                       format_number(range_um) +
                           " um is shorter than the longest membrane edge of " + morphology.name +
                           " (" + format_number(longest_um) +
                           " um): a vertex could pass between another cell's vertices");
    }
  }
}

namespace {

struct TubeLattice {
  geometry::TubeWall wall;
  geometry::LatticeGrid grid_um;
  geometry::SolidMask solid_mask;
};

std::unique_ptr<lattice::FluidSolver> tube_fluid(const TubeLattice& tube,
                                                 lattice::FluidParameters parameters,
                                                 double body_force_lu) {
  parameters.body_force = {body_force_lu, 0.0, 0.0};
  const auto& grid = tube.grid_um;
  auto solver = std::make_unique<lattice::FluidSolver>(
      lattice::LatticeGrid(grid.nx, grid.ny, grid.nz), parameters);
  for (std::size_t node = 0; node < tube.solid_mask.size(); ++node) {
    if (tube.solid_mask[node] == geometry::kSolid) solver->set_wall(node);
  }
  solver->set_wall_links(geometry::wall_link_fractions(tube.wall, grid, tube.solid_mask));
  return solver;
}

// Volumetric flow rate along x, lattice units: the sum of u_x over the fluid nodes per slice.
double flow_rate_lu(const lattice::FluidSolver& fluid) {
  const auto& mask = fluid.solid_mask();
  const auto& ux = fluid.velocity()[0];
  double sum = 0.0;
  for (std::size_t node = 0; node < ux.size(); ++node) {
    if (mask[node] == 0) sum += ux[node];
  }
  return sum / fluid.grid().nx();
}

double radial_um(const Vec3& position) { return std::hypot(position.y(), position.z()); }

// R - the mean over (x, angle) bins of the largest vertex radius in the bin; the fraction of
// bins that held a vertex.
std::pair<double, double> cell_free_layer_um(const coupling::CoupledSimulation& simulation,
                                             double radius_um, double length_um) {
  const int slices = std::max(1, static_cast<int>(std::round(length_um / kLayerBinUm)));
  const int sectors =
      std::max(4, static_cast<int>(std::round(2.0 * std::numbers::pi * radius_um / kLayerBinUm)));
  std::vector<double> outermost(static_cast<std::size_t>(slices * sectors), -1.0);
  for (std::size_t c = 0; c < simulation.cells().size(); ++c) {
    for (const Vec3& position : simulation.positions_now_um(c)) {
      const double x = position.x() - length_um * std::floor(position.x() / length_um);
      const int slice = std::min(slices - 1, static_cast<int>(x / length_um * slices));
      const double angle = std::atan2(position.z(), position.y()) + std::numbers::pi;
      const int sector =
          std::min(sectors - 1, static_cast<int>(angle / (2.0 * std::numbers::pi) * sectors));
      auto& bin = outermost[static_cast<std::size_t>(slice * sectors + sector)];
      bin = std::max(bin, radial_um(position));
    }
  }
  double sum = 0.0;
  std::size_t populated = 0;
  for (const double r : outermost) {
    if (r < 0.0) continue;
    sum += r;
    ++populated;
  }
  if (populated == 0) return {radius_um, 0.0};
  return {radius_um - sum / static_cast<double>(populated),
          static_cast<double>(populated) / static_cast<double>(outermost.size())};
}

// Every cell's surface now: its vertices (um) and triangles, gathered once per sample for the
// measures that need whole surfaces.
struct CellSurfaces {
  std::vector<std::vector<Vec3>> positions_um;
  std::vector<std::span<const mesh::Triangle>> triangles;
};

CellSurfaces surfaces_of(const coupling::CoupledSimulation& simulation) {
  CellSurfaces surfaces;
  for (std::size_t c = 0; c < simulation.cells().size(); ++c) {
    surfaces.positions_um.push_back(simulation.positions_now_um(c));
    surfaces.triangles.push_back(simulation.cell(c).model().triangles());
  }
  return surfaces;
}

// The cells' volume fraction in rings about the axis.
std::vector<double> hematocrit_profile(const CellSurfaces& surfaces,
                                       const SuspensionSettings& settings) {
  RadialProfileGrid grid;
  grid.radius_um = 0.5 * settings.tube_diameter_um;
  grid.length_um = settings.tube_length_um;
  grid.rings = settings.profile_rings;
  return radial_volume_fraction(surfaces.positions_um, surfaces.triangles, grid);
}

// How many cells have a vertex inside another cell, across the tube's periodic length.
std::size_t pierced_cell_count(const CellSurfaces& surfaces, double length_um) {
  const auto pierced = find_pierced_cells(surfaces.positions_um, surfaces.triangles,
                                          contact::PeriodicBox{{length_um, 0.0, 0.0}});
  return static_cast<std::size_t>(
      std::ranges::count_if(pierced, [](const auto& other) { return other.has_value(); }));
}

class SuspensionRecorder {
 public:
  // `sample_steps` receives the step of each sample, for the checkpoint (SuspensionRecord).
  SuspensionRecorder(SuspensionRun& run, std::vector<std::size_t>& sample_steps,
                     const SuspensionSettings& settings, std::vector<double> cell_volumes_um3,
                     double plasma_flow_lu)
      : run_(run),
        sample_steps_(sample_steps),
        settings_(settings),
        cell_volumes_um3_(std::move(cell_volumes_um3)),
        plasma_flow_lu_(plasma_flow_lu) {}

  void operator()(const coupling::CoupledSimulation& simulation) {
    const auto& units = simulation.units();
    const double dx_um = simulation.frame().dx_um;
    const double flow_lu = flow_rate_lu(simulation.fluid());
    const double um3_per_s = dx_um * dx_um * dx_um / simulation.frame().dt_s;
    const double radius_um = 0.5 * settings_.tube_diameter_um;
    const double lumen_um3 = std::numbers::pi * radius_um * radius_um * settings_.tube_length_um;

    // The cells' volume now: their reference's, while they grow.
    const double scale = simulation.cell_scale();
    const double volume_scale = scale * scale * scale;
    SuspensionSample sample;
    sample.time_s = simulation.time_s();
    sample.flow_rate_um3_per_s = flow_lu * um3_per_s;
    sample.relative_apparent_viscosity = plasma_flow_lu_ / flow_lu;
    double volume_um3 = 0.0;
    double volume_flux_um4_per_s = 0.0;
    for (std::size_t c = 0; c < simulation.cells().size(); ++c) {
      const auto& cell = simulation.cell(c);
      const double velocity_m_per_s = units.to_physical(PhysicalUnit::velocity_m_per_s,
                                                        mean_velocity(cell.velocities_lu()).x());
      volume_um3 += volume_scale * cell_volumes_um3_[c];
      volume_flux_um4_per_s += volume_scale * cell_volumes_um3_[c] * velocity_m_per_s * 1e6;
      const Vec3 centroid_um = simulation.frame().to_um(cell.centroid_lu());
      run_.cell_samples.push_back({sample.time_s, c, centroid_um, radial_um(centroid_um),
                                   velocity_m_per_s, deformation_index(cell.positions_lu())});
    }
    sample.tube_hematocrit = volume_um3 / lumen_um3;
    sample.discharge_hematocrit =
        volume_flux_um4_per_s / (sample.flow_rate_um3_per_s * settings_.tube_length_um);
    std::tie(sample.cell_free_layer_um, sample.populated_bin_fraction) =
        cell_free_layer_um(simulation, radius_um, settings_.tube_length_um);
    sample.contact_pairs = simulation.contact_statistics().pairs_in_range;
    sample.close_contact_pairs = simulation.contact_statistics().close_pairs;
    const auto surfaces = surfaces_of(simulation);
    sample.pierced_cells = pierced_cell_count(surfaces, settings_.tube_length_um);
    if (sample.pierced_cells > 0) ++run_.samples_with_pierced_cells;
    sample.volume_fraction_by_ring = hematocrit_profile(surfaces, settings_);
    run_.samples.push_back(sample);
    sample_steps_.push_back(simulation.time_step());
  }

 private:
  SuspensionRun& run_;
  std::vector<std::size_t>& sample_steps_;
  const SuspensionSettings& settings_;
  std::vector<double> cell_volumes_um3_;
  double plasma_flow_lu_;
};

// Values per sample and per cell sample in the checkpoint.
constexpr std::size_t kSuspensionSampleValues = 11;
constexpr std::size_t kSuspensionCellSampleValues = 8;

// Never stops the run: it carries the samples recorded so far in the checkpoint, so that a resumed
// run reports what a straight one would. An interrupted run's observers also see the state reached
// between two sample intervals; that sample (and its cells') is reported by the interrupted run
// but left out of the checkpoint, which a straight run would not have.
class SuspensionRecord final : public coupling::StopCriterion {
 public:
  SuspensionRecord(SuspensionRun& run, std::vector<std::size_t>& sample_steps,
                   std::size_t interval_steps, std::size_t cell_count, std::size_t rings)
      : run_(run),
        sample_steps_(sample_steps),
        interval_steps_(interval_steps),
        cell_count_(cell_count),
        rings_(rings) {}

  std::optional<std::string> check(const coupling::CoupledSimulation& /*simulation*/) override {
    return std::nullopt;
  }

  void save_state(StateArchive& archive, const std::string& prefix) const override {
    std::vector<double> samples, cells, profiles;
    for (std::size_t i = 0; i < run_.samples.size(); ++i) {
      if (sample_steps_[i] % interval_steps_ != 0) continue;
      const auto& s = run_.samples[i];
      samples.insert(
          samples.end(),
          {static_cast<double>(sample_steps_[i]), s.time_s, s.flow_rate_um3_per_s,
           s.relative_apparent_viscosity, s.tube_hematocrit, s.discharge_hematocrit,
           s.cell_free_layer_um, s.populated_bin_fraction, static_cast<double>(s.contact_pairs),
           static_cast<double>(s.close_contact_pairs), static_cast<double>(s.pierced_cells)});
      profiles.insert(profiles.end(), s.volume_fraction_by_ring.begin(),
                      s.volume_fraction_by_ring.end());
      for (std::size_t c = 0; c < cell_count_; ++c) {
        const auto& cell = run_.cell_samples[i * cell_count_ + c];
        cells.insert(cells.end(),
                     {cell.time_s, static_cast<double>(cell.cell), cell.centroid_um.x(),
                      cell.centroid_um.y(), cell.centroid_um.z(), cell.radial_position_um,
                      cell.velocity_x_m_per_s, cell.deformation_index});
      }
    }
    archive.put(prefix + "samples", std::move(samples));
    archive.put(prefix + "cell_samples", std::move(cells));
    archive.put(prefix + "profiles", std::move(profiles));
  }

  void restore_state(StateArchive& archive, const std::string& prefix) override {
    const auto samples = archive.take(prefix + "samples", std::nullopt);
    if (samples.size() % kSuspensionSampleValues != 0) {
      throw InputError(archive.source(), prefix + "samples: not whole samples");
    }
    const std::size_t count = samples.size() / kSuspensionSampleValues;
    const auto cells =
        archive.take(prefix + "cell_samples", count * cell_count_ * kSuspensionCellSampleValues);
    const auto profiles = archive.take(prefix + "profiles", count * rings_);
    run_.samples.clear();
    run_.cell_samples.clear();
    sample_steps_.clear();
    run_.samples_with_pierced_cells = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const auto* v = samples.data() + i * kSuspensionSampleValues;
      sample_steps_.push_back(static_cast<std::size_t>(v[0]));
      const auto ring_values = profiles.begin() + static_cast<std::ptrdiff_t>(i * rings_);
      run_.samples.push_back(
          {v[1], v[2], v[3], v[4], v[5], v[6], v[7], static_cast<std::size_t>(v[8]),
           static_cast<std::size_t>(v[9]), static_cast<std::size_t>(v[10]),
           std::vector<double>(ring_values, ring_values + static_cast<std::ptrdiff_t>(rings_))});
      if (run_.samples.back().pierced_cells > 0) ++run_.samples_with_pierced_cells;
    }
    for (std::size_t k = 0; k < count * cell_count_; ++k) {
      const auto* v = cells.data() + k * kSuspensionCellSampleValues;
      run_.cell_samples.push_back(
          {v[0], static_cast<std::size_t>(v[1]), Vec3(v[2], v[3], v[4]), v[5], v[6], v[7]});
    }
  }

 private:
  SuspensionRun& run_;
  std::vector<std::size_t>& sample_steps_;
  std::size_t interval_steps_;
  std::size_t cell_count_;
  std::size_t rings_;
};

// The averaging window: the last `fraction` of the run, never the release (t = 0), which is a
// packing and not a developed flow even when the window is the whole run.
struct AveragingWindow {
  double from_s;
  explicit AveragingWindow(double end_s, double fraction) : from_s(end_s * (1.0 - fraction)) {}
  [[nodiscard]] bool contains(double time_s) const { return time_s >= from_s && time_s != 0.0; }
};

SuspensionAverages averages_of(const std::vector<SuspensionSample>& samples, double end_s,
                               double fraction) {
  SuspensionAverages averages;
  const AveragingWindow window(end_s, fraction);
  std::vector<double> viscosities;
  for (const auto& sample : samples) {
    if (!window.contains(sample.time_s)) continue;
    ++averages.samples;
    viscosities.push_back(sample.relative_apparent_viscosity);
    averages.tube_hematocrit += sample.tube_hematocrit;
    averages.discharge_hematocrit += sample.discharge_hematocrit;
    averages.cell_free_layer_um += sample.cell_free_layer_um;
  }
  if (averages.samples == 0) return averages;
  const double n = static_cast<double>(averages.samples);
  for (const auto& sample : samples) {
    if (!window.contains(sample.time_s)) continue;
    auto& profile = averages.volume_fraction_by_ring;
    profile.resize(sample.volume_fraction_by_ring.size(), 0.0);
    for (std::size_t ring = 0; ring < profile.size(); ++ring) {
      profile[ring] += sample.volume_fraction_by_ring[ring] / n;
    }
  }
  averages.tube_hematocrit /= n;
  averages.discharge_hematocrit /= n;
  averages.cell_free_layer_um /= n;
  const auto viscosity = spread_of(viscosities);
  averages.relative_apparent_viscosity = viscosity.mean;
  averages.relative_apparent_viscosity_sd = viscosity.standard_deviation;
  return averages;
}

std::size_t interval_steps(const units::UnitConverter& units, double interval_s) {
  const double steps = std::round(units.to_lattice(PhysicalUnit::time_s, interval_s));
  return std::max<std::size_t>(1, static_cast<std::size_t>(steps));
}

}  // namespace

std::vector<std::size_t> cell_counts_for(double hematocrit, double lumen_volume_um3,
                                         std::span<const double> fractions,
                                         std::span<const double> cell_volumes_um3) {
  double mean_volume_um3 = 0.0;
  for (std::size_t m = 0; m < fractions.size(); ++m) {
    mean_volume_um3 += fractions[m] * cell_volumes_um3[m];
  }
  const auto total =
      static_cast<std::size_t>(std::llround(hematocrit * lumen_volume_um3 / mean_volume_um3));
  if (total == 0) {
    throw InputError("suspension.hematocrit",
                     format_number(hematocrit) + " puts no whole cell in the tube (" +
                         format_number(lumen_volume_um3) + " um^3); raise it or lengthen the tube");
  }
  // Largest remainders: floors first, then one more to the largest fractional parts (ties to the
  // earlier morphology).
  std::vector<std::size_t> counts;
  std::vector<std::pair<double, std::size_t>> remainders;
  std::size_t assigned = 0;
  for (std::size_t m = 0; m < fractions.size(); ++m) {
    const double exact = fractions[m] * static_cast<double>(total);
    counts.push_back(static_cast<std::size_t>(std::floor(exact)));
    assigned += counts.back();
    remainders.push_back({-(exact - std::floor(exact)), m});
  }
  std::sort(remainders.begin(), remainders.end());
  for (std::size_t k = 0; assigned < total; ++k, ++assigned) ++counts[remainders[k].second];
  return counts;
}

void add_suspension_walls(coupling::CoupledSimulation& simulation,
                          std::span<const SuspensionMorphology> morphologies,
                          std::span<const std::size_t> cell_morphologies,
                          const WallRepulsion& per_um2, const SuspensionWall& wall) {
  std::vector<WallRepulsion> repulsions;
  for (const auto& morphology : morphologies) {
    repulsions.push_back({per_um2.force_at_wall_pN * mesh::surface_area_um2(morphology.mesh) /
                              static_cast<double>(morphology.mesh.vertex_count()),
                          per_um2.range_um, per_um2.law});
  }
  const std::vector<std::size_t> kinds(cell_morphologies.begin(), cell_morphologies.end());
  simulation.add_external_force([repulsions, kinds, wall](std::size_t c, const coupling::Cell& cell,
                                                          std::span<Vec3> forces_pN) {
    add_wall_repulsion(cell.positions_um(), wall, repulsions[kinds[c]], forces_pN);
  });
}

SuspensionEnd run_to_end(coupling::CoupledSimulation& simulation) {
  SuspensionEnd end;
  try {
    end.stop_reason = simulation.run().stop_reason;
  } catch (const Interrupted& interrupted) {
    end.interrupted = true;
    end.stop_reason = end.failure = interrupted.what();
  } catch (const RuntimeFailure& failure) {
    // The run stopped at the failure: say so where the stop reason is read (the summary line).
    end.stop_reason = end.failure = failure.what();
  }
  return end;
}

SuspensionRun run_suspension(std::span<const SuspensionMorphology> morphologies,
                             std::span<const std::size_t> cell_morphologies,
                             const SuspensionPhysics& physics, const SuspensionSettings& settings,
                             const SuspensionConfigure& configure) {
  validate(settings);
  require_contact_reaches_across_edges(morphologies, settings.contact.range_um);
  const double radius_um = 0.5 * settings.tube_diameter_um;
  std::vector<mesh::TriangleMesh> meshes;
  for (const auto& morphology : morphologies) meshes.push_back(morphology.mesh);
  const PackingTube packing_tube{radius_um, settings.tube_length_um};
  const Packing packing =
      settings.placed_cells.empty()
          ? pack_cells_in_tube(meshes, cell_morphologies, packing_tube, settings.packing)
          : place_cells_in_tube(meshes, cell_morphologies, settings.placed_cells, packing_tube,
                                settings.packing);

  SuspensionRun run;
  run.cell_morphologies.assign(cell_morphologies.begin(), cell_morphologies.end());
  run.packed_hematocrit = packing.hematocrit;
  run.packing_iterations = packing.iterations;

  const double dx_um = physics.units.dx_m() * 1e6;
  TubeLattice tube{
      geometry::TubeWall({settings.tube_diameter_um, settings.tube_length_um}, "suspension"),
      {},
      {}};
  tube.grid_um = geometry::lattice_around(tube.wall, dx_um);
  tube.solid_mask = geometry::voxelise(tube.wall, tube.grid_um);
  physics.units.check_lattice_velocity(2.0 * settings.plasma_mean_velocity_m_per_s,
                                       "suspension.plasma_mean_velocity_m_per_s (peak velocity)");
  // Poiseuille: mean velocity U = G R^2 / (8 rho nu), so the force density G = 8 rho nu U / R^2.
  const double velocity_lu = physics.units.to_lattice(PhysicalUnit::velocity_m_per_s,
                                                      settings.plasma_mean_velocity_m_per_s);
  const double radius_lu = radius_um / dx_um;
  const double body_force_lu =
      8.0 * physics.units.lattice_kinematic_viscosity() * velocity_lu / (radius_lu * radius_lu);
  run.pressure_gradient_Pa_per_m =
      physics.units.to_physical(PhysicalUnit::force_density_N_per_m3, body_force_lu);
  run.pseudo_shear_rate_per_s =
      settings.plasma_mean_velocity_m_per_s / (settings.tube_diameter_um * 1e-6);

  auto fluid = tube_fluid(tube, physics.fluid, body_force_lu);
  // Across the run's processes, in slabs.
  const auto steady = parallel::run_to_steady_state(
      physics.coupling.processes, *fluid, physics.coupling.block_planes,
      {settings.fluid_tolerance, 100, settings.fluid_max_steps});
  run.fluid_settling_steps = steady.steps;
  if (!steady.converged) {
    run.failure = "the plasma alone did not reach its steady state in " +
                  std::to_string(steady.steps) + " steps";
    return run;
  }
  const double plasma_flow_lu = flow_rate_lu(*fluid);
  run.plasma_flow_rate_um3_per_s = plasma_flow_lu * dx_um * dx_um * dx_um / physics.units.dt_s();

  coupling::CoupledSimulation simulation(std::move(fluid), physics.units, physics.coupling,
                                         tube.grid_um.origin_um);
  if (packing.scale < 1.0) {
    simulation.grow_cells(cell_growth_for(physics.units, packing.scale, settings.growth_time_s));
  }
  std::vector<double> cell_volumes_um3;
  for (std::size_t c = 0; c < cell_morphologies.size(); ++c) {
    const auto& morphology = morphologies[cell_morphologies[c]];
    simulation.add_cell(membrane::MembraneModel(morphology.mesh, morphology.membrane),
                        packing.positions_um[c]);
    cell_volumes_um3.push_back(mesh::enclosed_volume_um3(morphology.mesh));
  }
  add_suspension_walls(
      simulation, morphologies, cell_morphologies,
      {settings.wall_repulsion_pN_per_um2, settings.wall_repulsion_range_um, settings.wall_law},
      [radius_um](const Vec3& position) { return tube_wall_distance(position, radius_um); });
  simulation.set_cell_contact(settings.contact, "suspension.contact_force_pN");
  const std::size_t sample_steps = interval_steps(physics.units, settings.sample_interval_s);
  std::vector<std::size_t> sampled_at_steps;
  coupling::Observer recorder{
      "suspension_samples", sample_steps,
      SuspensionRecorder(run, sampled_at_steps, settings, cell_volumes_um3, plasma_flow_lu)};
  recorder.reads_fluid = true;  // the flow rate
  simulation.add_observer(std::move(recorder));
  simulation.add_stop_criterion(coupling::stop_at_time(settings.duration_s));
  simulation.add_stop_criterion(std::make_unique<SuspensionRecord>(
      run, sampled_at_steps, sample_steps, cell_morphologies.size(), settings.profile_rings));
  if (configure) configure(simulation);
  const auto record_end = [&run, &simulation] {
    run.steps = simulation.time_step();
    run.time_s = simulation.time_s();
    run.close_contact_steps = simulation.close_contact_steps();
    run.capped_contact_steps = simulation.capped_contact_steps();
    run.force_capped_steps = simulation.capped_steps_per_cell();
    run.phase_times = simulation.phase_times();
    run.sub_spacing_drag = simulation.sub_spacing_drag_summary();
  };
  const auto end = run_to_end(simulation);
  run.stop_reason = end.stop_reason;
  run.failure = end.failure;
  run.interrupted = end.interrupted;
  record_end();
  run.averages = averages_of(run.samples, run.time_s, settings.averaging_fraction);
  run.averages.by_morphology =
      morphology_averages(run.cell_samples, run.cell_morphologies, morphologies.size(), run.time_s,
                          settings.averaging_fraction);
  return run;
}

std::vector<MorphologyAverages> morphology_averages(std::span<const SuspensionCellSample> samples,
                                                    std::span<const std::size_t> cell_morphologies,
                                                    std::size_t morphology_count, double end_s,
                                                    double fraction) {
  std::vector<MorphologyAverages> averages(morphology_count);
  const AveragingWindow window(end_s, fraction);
  for (const auto& sample : samples) {
    if (!window.contains(sample.time_s)) continue;
    auto& kind = averages.at(cell_morphologies[sample.cell]);
    ++kind.cell_samples;
    kind.radial_position_um += sample.radial_position_um;
    kind.velocity_x_m_per_s += sample.velocity_x_m_per_s;
    kind.deformation_index += sample.deformation_index;
  }
  for (auto& kind : averages) {
    if (kind.cell_samples == 0) continue;
    const double n = static_cast<double>(kind.cell_samples);
    kind.radial_position_um /= n;
    kind.velocity_x_m_per_s /= n;
    kind.deformation_index /= n;
  }
  return averages;
}

double mean_cell_travel_um(std::span<const SuspensionCellSample> samples) {
  std::vector<TrackSample> along_axis;
  along_axis.reserve(samples.size());
  for (const auto& sample : samples) {
    along_axis.push_back({sample.cell, sample.time_s, sample.centroid_um.x()});
  }
  return mean_change_per_track(along_axis);
}

}  // namespace rbcsim::cases
