#include "cases/shear_case.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <span>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/registry.hpp"
#include "common/state_archive.hpp"
#include "common/thread_count_scope.hpp"
#include "common/wall_clock.hpp"
#include "coupling/stop_criteria.hpp"
#include "membrane/cell_geometry.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::cases {
namespace {

// The symmetry axis counts as z when the least-variance principal axis is this close to it: a
// generated shape has it on z up to round-off, a mesh that does not is aligned first.
constexpr double kSymmetryAxisCosineTolerance = 1e-6;
// Record samples per check interval: the tank-treading point must turn by less than pi between
// two samples (a tank-treading membrane turns at about rate / 2, 0.5 rad per unit strain; the
// tips of an elongated cell faster).
constexpr std::size_t kSamplesPerCheck = 4;

struct ShearBoundary {
  std::string_view name;
  int wall_layers;
  // Sets the boundary of a fluid whose gap moves at -/+ velocity_difference / 2.
  void (*install)(lattice::FluidParameters& parameters, double velocity_difference);
  void (*add_walls)(lattice::FluidSolver& fluid, double velocity_difference);
};

void sliding_images(lattice::FluidParameters& parameters, double velocity_difference) {
  parameters.lees_edwards_velocity = velocity_difference;
}

void no_walls(lattice::FluidSolver&, double) {}

void no_sliding(lattice::FluidParameters&, double) {}

// Wall nodes in the planes y = 0 and y = ny - 1: half-way walls at y = 1/2 and y = ny - 3/2.
void moving_walls(lattice::FluidSolver& fluid, double velocity_difference) {
  const auto& grid = fluid.grid();
  const int ny = grid.ny();
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) {
      fluid.set_wall(grid.index(x, 0, z), {-0.5 * velocity_difference, 0.0, 0.0});
      fluid.set_wall(grid.index(x, ny - 1, z), {0.5 * velocity_difference, 0.0, 0.0});
    }
  }
}

constexpr ShearBoundary kBoundaries[] = {
    {"lees-edwards", 0, sliding_images, no_walls},
    {"walls", 1, no_sliding, moving_walls},
};

const ShearBoundary& find_boundary(std::string_view name) {
  return find_entry(std::span<const ShearBoundary>(kBoundaries), name, "shear.boundary");
}

int nodes_for(double length_um, double dx_um) {
  return static_cast<int>(std::ceil(length_um / dx_um - 1e-9));
}

// Where node (0, 0, 0) sits so that the box centre is at the origin (the cell's centre).
Vec3 box_origin_um(const ShearBox& box, double dx_um) {
  return -0.5 * dx_um * Vec3(box.nx - 1, box.ny - 1, box.nz - 1);
}

units::UnitConverter simulated_units(const ShearEngine& engine, const ShearRatePlan& plan) {
  auto lattice = engine.lattice;
  lattice.kinematic_viscosity_m2_per_s = plan.simulated_kinematic_viscosity_m2_per_s;
  return units::UnitConverter(lattice);
}

// What ShearRecord needs to know of its rate.
struct RecordSetup {
  std::size_t tracked_vertex = 0;
  std::size_t sample_interval_steps = 1;
  double strain_per_sample = 0.0;     // in the rate's strain units (ShearPoint::strain)
  double time_unit_rate_per_s = 0.0;  // simulated rate (rate 0: its time unit)
  bool rotating = false;              // rate > 0: the windows are half turns of the tracked point
  double tolerance_per_strain = 0.0;
  WallClock::time_point started;  // when the rate started: its wall time
};

// A rate's record and its steady state (shear_case.hpp, "Steady state"). The first stop criterion
// of the rate, so it sees every step: every sample_interval_steps it samples the tracked point's
// unwrapped angle and the cell's shape, and every kSamplesPerCheck samples it compares the shape's
// means over the last window with those over the window before. Its series, its count of
// steady checks and the rate's wall time so far ride in the checkpoint, so a resumed rate ends as
// a straight one and reports the time of both runs.
class ShearRecord final : public coupling::StopCriterion {
 public:
  ShearRecord(RecordSetup setup, bool& steady) : setup_(setup), steady_(steady) {}

  double wall_time_s() const { return seconds_since(setup_.started); }

  std::optional<std::string> check(const coupling::CoupledSimulation& simulation) override {
    const std::size_t step = simulation.time_step();
    if (step % setup_.sample_interval_steps != 0) return std::nullopt;
    sample(simulation);
    if ((step / setup_.sample_interval_steps) % kSamplesPerCheck != 0) return std::nullopt;
    steady_checks_ = window_is_steady() ? steady_checks_ + 1 : 0;
    if (steady_checks_ < kSteadyChecksInARow) return std::nullopt;
    steady_ = true;
    return "steady: the mean length and breadth over the last " +
           format_significant(window_strain(window_samples())) + " strain within " +
           format_number(setup_.tolerance_per_strain) + " per strain of the window before, " +
           std::to_string(kSteadyChecksInARow) + " checks in a row";
  }

  // Over the second half of the run (the first is the start-up); 0 with too few samples.
  double frequency_hz() const {
    if (times_s_.size() < 2) return 0.0;
    const double half_s = 0.5 * times_s_.back();
    const auto first = static_cast<std::size_t>(
        std::lower_bound(times_s_.begin(), times_s_.end(), half_s) - times_s_.begin());
    if (times_s_.size() - first < 2) return 0.0;
    return rotation_frequency_hz(std::span(times_s_).subspan(first),
                                 std::span(angles_rad_).subspan(first));
  }

  // The shape averaged over the last window and that window's strain; nothing before the first
  // whole window.
  std::optional<std::pair<AveragedShape, double>> averaged_shape() const {
    const std::size_t n = window_samples();
    if (n == 0 || n > shapes_.size()) return std::nullopt;
    return std::pair{average_shapes(std::span(shapes_).last(n)), window_strain(n)};
  }

  std::vector<ShearSample> history() const {
    std::vector<ShearSample> samples;
    for (std::size_t i = 0; i < times_s_.size(); ++i) {
      samples.push_back({times_s_[i] * setup_.time_unit_rate_per_s, shapes_[i]});
    }
    return samples;
  }

  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put(prefix + "times_s", times_s_);
    archive.put(prefix + "angles_rad", angles_rad_);
    for (const auto& [name, member] : kShapeSeries) {
      std::vector<double> values;
      for (const ShearShape& shape : shapes_) values.push_back(shape.*member);
      archive.put(prefix + name, std::move(values));
    }
    archive.put(prefix + "steady_checks", {static_cast<double>(steady_checks_)});
    archive.put(prefix + "wall_time_s", {wall_time_s()});
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    times_s_ = archive.take(prefix + "times_s", std::nullopt);
    angles_rad_ = archive.take(prefix + "angles_rad", times_s_.size());
    shapes_.assign(times_s_.size(), ShearShape{});
    for (const auto& [name, member] : kShapeSeries) {
      const auto values = archive.take(prefix + name, times_s_.size());
      for (std::size_t i = 0; i < values.size(); ++i) shapes_[i].*member = values[i];
    }
    steady_checks_ = static_cast<int>(archive.take(prefix + "steady_checks", 1).front());
    // The rate "started" that much before now: its wall time goes on from the checkpoint's.
    setup_.started = started_seconds_ago(archive.take_number(prefix + "wall_time_s"));
  }

 private:
  static constexpr int kSteadyChecksInARow = 3;  // a window pair can agree by chance once
  static constexpr std::array<std::pair<const char*, double ShearShape::*>, 4> kShapeSeries{
      {{"lengths_um", &ShearShape::length_um},
       {"breadths_um", &ShearShape::breadth_um},
       {"deformation_indices", &ShearShape::deformation_index},
       {"inclinations_deg", &ShearShape::inclination_deg}}};

  void sample(const coupling::CoupledSimulation& simulation) {
    const auto& cell = simulation.cell(0);
    const double angle =
        in_plane_angle_rad(cell.positions_lu()[setup_.tracked_vertex], cell.centroid_lu());
    angles_rad_.push_back(angles_rad_.empty() ? angle
                                              : unwrap_angle_rad(angles_rad_.back(), angle));
    times_s_.push_back(simulation.time_s());
    shapes_.push_back(measure_shear_shape(simulation.positions_now_um(0)));
  }

  // Samples per window: the tracked point's last half turn (one swinging period) but one check
  // interval at least; one check interval at rate 0. 0 while the point has not turned by pi.
  std::size_t window_samples() const {
    if (!setup_.rotating) return kSamplesPerCheck;
    const std::size_t half_turn = samples_in_last_half_turn(angles_rad_);
    return half_turn == 0 ? 0 : std::max<std::size_t>(half_turn, kSamplesPerCheck);
  }

  double window_strain(std::size_t samples) const {
    return static_cast<double>(samples) * setup_.strain_per_sample;
  }

  // The last window against the one before: length and breadth each within the tolerance per
  // strain between the windows' centres.
  bool window_is_steady() const {
    const std::size_t n = window_samples();
    if (n == 0 || 2 * n > shapes_.size()) return false;
    const auto shapes = std::span(shapes_);
    const auto last = average_shapes(shapes.last(n)).mean;
    const auto before = average_shapes(shapes.last(2 * n).first(n)).mean;
    const double allowed = setup_.tolerance_per_strain * window_strain(n);
    return std::abs(last.length_um - before.length_um) <= allowed * last.length_um &&
           std::abs(last.breadth_um - before.breadth_um) <= allowed * last.breadth_um;
  }

  RecordSetup setup_;
  bool& steady_;
  int steady_checks_ = 0;
  std::vector<double> times_s_;
  std::vector<double> angles_rad_;
  std::vector<ShearShape> shapes_;
};

// The vertex farthest along +x: on the rim of a cell whose axis is y, in the shear plane.
std::size_t tracked_vertex(const mesh::TriangleMesh& cell) {
  const auto& p = cell.positions_um;
  return static_cast<std::size_t>(
      std::max_element(p.begin(), p.end(),
                       [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); }) -
      p.begin());
}

// The smoothness and roughness of the cell's surface now (shear_observables.hpp), and its area
// strain.
void measure_surface(const membrane::MembraneModel& model, std::span<const Vec3> positions_um,
                     ShearPoint& point) {
  membrane::CellGeometry geometry(model.topology().triangle_count(), model.topology().edge_count());
  membrane::measure_cell_geometry(positions_um, model.triangles(), model.topology(), geometry);
  const auto& reference_rad = model.reference().dihedral_angles_rad;
  point.smoothness_rad = dihedral_change_rms_rad(geometry.dihedral_angles_rad, reference_rad);
  point.roughness_rad =
      dihedral_roughness_rad(geometry.dihedral_angles_rad, reference_rad, model.topology());
  point.area_strain =
      mesh::area_strain(positions_um, model.triangles(), model.reference().triangle_areas_um2);
}

std::size_t steps_for(double strain, double strain_rate_lu) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(strain / strain_rate_lu)));
}

}  // namespace

ShearBox shear_box(const mesh::TriangleMesh& cell, double dx_um, const ShearSettings& settings) {
  const double diameter_um = largest_vertex_distance_um(cell.positions_um);
  ShearBox box;
  box.wall_layers = find_boundary(settings.boundary).wall_layers;
  box.nx = nodes_for(settings.width_diameters * diameter_um, dx_um);
  box.nz = box.nx;
  box.ny = nodes_for(settings.gap_diameters * diameter_um, dx_um) + 2 * box.wall_layers;
  return box;
}

std::string shear_rate_directory(std::size_t rate_index) {
  std::array<char, 32> name{};
  std::snprintf(name.data(), name.size(), "rate_%03zu", rate_index);
  return name.data();
}

std::vector<std::string> shear_boundary_names() {
  return entry_names(std::span<const ShearBoundary>(kBoundaries));
}

std::unique_ptr<lattice::FluidSolver> shear_fluid(const ShearBox& box,
                                                  const lattice::FluidParameters& parameters,
                                                  std::string_view boundary_name,
                                                  double shear_rate_lu) {
  const auto& boundary = find_boundary(boundary_name);
  const double velocity_difference = shear_rate_lu * box.gap_nodes();
  auto with_boundary = parameters;
  boundary.install(with_boundary, velocity_difference);
  auto fluid = std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(box.nx, box.ny, box.nz),
                                                      with_boundary);
  boundary.add_walls(*fluid, velocity_difference);
  const std::size_t node_count = fluid->grid().node_count();
  lattice::VectorField velocity{std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0)};
  const double middle = 0.5 * (box.ny - 1);
  for (std::size_t node = 0; node < node_count; ++node) {
    velocity[0][node] = shear_rate_lu * (fluid->grid().coordinates(node)[1] - middle);
  }
  fluid->initialise_equilibrium(std::vector<double>(node_count, 1.0), velocity);
  return fluid;
}

mesh::TriangleMesh in_shear_frame(mesh::TriangleMesh mesh) {
  const Eigen::Matrix3d axes = mesh::principal_axes(mesh);
  if (std::abs(axes.col(2).z()) < 1.0 - kSymmetryAxisCosineTolerance)
    mesh::align_principal_axes(mesh);
  const Vec3 centroid = mesh::solid_centroid_um(mesh);
  // A proper rotation about x taking z to y: (x, y, z) -> (x, z, -y).
  for (Vec3& p : mesh.positions_um) {
    const Vec3 r = p - centroid;
    p = Vec3(r.x(), r.z(), -r.y());
  }
  return mesh;
}

double link_shear_modulus_N_per_m(const membrane::MembraneModel& model) {
  const auto& parameters = model.parameters();
  const auto& forces = parameters.forces;
  if (std::find(forces.begin(), forces.end(), "link") == forces.end()) return 0.0;
  const auto& lengths = model.reference().edge_lengths_um;
  double mean_length_um = 0.0;
  for (double length : lengths) mean_length_um += length / static_cast<double>(lengths.size());
  // pN um / (um um) = pN / um = 1e-6 N/m.
  const double spring_pN_per_um = parameters.k_link_kBT * parameters.thermal_energy_pN_um *
                                  (1.0 + 1.0 / (parameters.tau_link * parameters.tau_link)) /
                                  (parameters.persistence_length_um * mean_length_um);
  return std::sqrt(3.0) / 4.0 * spring_pN_per_um * 1e-6;
}

std::vector<ShearRatePlan> plan_shear_rates(const membrane::MembraneModel& model,
                                            const mesh::TriangleMesh& cell,
                                            const ShearEngine& engine,
                                            const ShearSettings& settings) {
  const double dx_um = engine.lattice.spacing_um;
  const ShearBox box = shear_box(cell, dx_um, settings);
  const double radius_m = 0.5e-6 * largest_vertex_distance_um(cell.positions_um);
  const double nu = engine.lattice.kinematic_viscosity_m2_per_s;
  const double shear_modulus = link_shear_modulus_N_per_m(model);
  const double half_gap_m = 0.5e-6 * dx_um * box.gap_nodes();
  std::vector<ShearRatePlan> plans;
  for (double rate : settings.rates_per_s) {
    if (!(rate >= 0.0)) {
      throw InputError("shear.rates_per_s", "rates must be >= 0 1/s, not " + format_number(rate));
    }
    ShearRatePlan plan;
    plan.shear_rate_per_s = rate;
    const double physical_reynolds = rate * radius_m * radius_m / nu;
    if (settings.viscosity_scaling && rate > 0.0 &&
        physical_reynolds < settings.max_reynolds_number) {
      plan.viscosity_scale = std::sqrt(settings.max_reynolds_number / physical_reynolds);
    }
    plan.simulated_shear_rate_per_s = rate * plan.viscosity_scale;
    plan.simulated_kinematic_viscosity_m2_per_s = nu / plan.viscosity_scale;
    plan.reynolds_number = physical_reynolds * plan.viscosity_scale * plan.viscosity_scale;
    plan.capillary_number = shear_modulus > 0.0 ? engine.lattice.density_kg_per_m3 * nu * rate *
                                                      radius_m / shear_modulus
                                                : std::numeric_limits<double>::quiet_NaN();
    const auto units = simulated_units(engine, plan);
    // Rate 0 keeps time in units of a rate at the Reynolds limit.
    const double time_unit_rate = rate > 0.0
                                      ? plan.simulated_shear_rate_per_s
                                      : settings.max_reynolds_number * nu / (radius_m * radius_m);
    plan.strain_rate_lu = time_unit_rate * units.dt_s();
    units.check_lattice_velocity(plan.simulated_shear_rate_per_s * half_gap_m,
                                 "shear rate " + format_number(rate) + " 1/s (simulated " +
                                     format_number(plan.simulated_shear_rate_per_s) +
                                     " 1/s): fluid speed at the boundary");
    plans.push_back(plan);
  }
  return plans;
}

ShearPoint run_shear_rate(const membrane::MembraneModel& model, const mesh::TriangleMesh& cell,
                          const ShearEngine& engine, const ShearSettings& settings,
                          const ShearRatePlan& plan, std::size_t rate_index,
                          const ShearHooks& hooks) {
  const auto started = WallClock::now();
  const double dx_um = engine.lattice.spacing_um;
  const ShearBox box = shear_box(cell, dx_um, settings);
  const auto units = simulated_units(engine, plan);
  const double flow_rate_lu = plan.shear_rate_per_s > 0.0 ? plan.strain_rate_lu : 0.0;
  auto coupling = engine.coupling;
  if (!coupling.run_directory.empty()) coupling.run_directory /= shear_rate_directory(rate_index);

  coupling::CoupledSimulation simulation(
      shear_fluid(box, engine.fluid, settings.boundary, flow_rate_lu), units, coupling,
      box_origin_um(box, dx_um));
  // With the viscosity scaled down, the membrane's viscosity follows, so its ratio to the
  // plasma's (the Boussinesq number) is the physical one.
  auto membrane_parameters = model.parameters();
  membrane_parameters.viscosity_Pa_s_um /= plan.viscosity_scale;
  simulation.add_cell(membrane::MembraneModel(cell, membrane_parameters), cell.positions_um);
  const double time_unit_rate = plan.strain_rate_lu / units.dt_s();
  const auto sample_interval_steps = steps_for(
      settings.check_interval_strain / static_cast<double>(kSamplesPerCheck), plan.strain_rate_lu);
  bool steady = false;
  auto owned_record = std::make_unique<ShearRecord>(
      RecordSetup{
          .tracked_vertex = tracked_vertex(cell),
          .sample_interval_steps = sample_interval_steps,
          .strain_per_sample = static_cast<double>(sample_interval_steps) * plan.strain_rate_lu,
          .time_unit_rate_per_s = time_unit_rate,
          .rotating = plan.shear_rate_per_s > 0.0,
          .tolerance_per_strain = settings.steady_tolerance_per_strain,
          .started = started},
      steady);
  const ShearRecord& record = *owned_record;  // the simulation owns it from here
  simulation.add_stop_criterion(std::move(owned_record));
  simulation.add_stop_criterion(coupling::stop_at_time(settings.max_strain / time_unit_rate));
  if (hooks.configure) hooks.configure(rate_index, simulation);

  ShearPoint point;
  point.plan = plan;
  try {
    point.stop_reason = simulation.run().stop_reason;
    point.steady = steady;
  } catch (const Interrupted& interrupted) {
    point.interrupted = true;
    point.failure = interrupted.what();
  } catch (const RuntimeFailure& failure) {
    point.failure = failure.what();
  }
  // From the simulation's counters (restored on resume), not from this run() call's summary.
  point.force_cap_steps = simulation.capped_steps_per_cell().at(0);
  point.sub_spacing_drag = simulation.sub_spacing_drag_summary();
  const auto positions_um = simulation.positions_now_um(0);
  if (const auto averaged = record.averaged_shape()) {
    point.shape = averaged->first.mean;
    point.length_swing_um = averaged->first.length_swing_um;
    point.window_strain = averaged->second;
  } else {
    point.shape = measure_shear_shape(positions_um);
  }
  measure_surface(model, positions_um, point);
  // At rate 0 nothing turns: the tracked vertex's drift at rest would give a frequency of
  // round-off size (1e-34 Hz), not a rotation.
  point.tank_treading_hz =
      plan.shear_rate_per_s > 0.0 ? record.frequency_hz() / plan.viscosity_scale : 0.0;
  point.history = record.history();
  point.steps = simulation.time_step();
  point.strain = simulation.time_s() * time_unit_rate;
  point.time_s = simulation.time_s() * plan.viscosity_scale;
  point.wall_time_s = record.wall_time_s();
  if (point.failure.empty() && hooks.finished) {
    simulation.add_term_forces();  // the shape file shows each term's forces
    hooks.finished(rate_index, point, simulation);
  }
  return point;
}

namespace {

// A rate of a sweep: the point it already has (resume), none if interrupted before it started,
// or its run.
ShearPoint sweep_rate(const membrane::MembraneModel& model, const mesh::TriangleMesh& cell,
                      const ShearEngine& engine, const ShearSettings& settings,
                      const ShearRatePlan& plan, std::size_t rate_index, const ShearHooks& hooks) {
  if (rate_index < hooks.completed.size() && hooks.completed[rate_index]) {
    return *hooks.completed[rate_index];
  }
  // Across processes all agree, so that none starts a rate the others skip.
  if (engine.coupling.processes.any(interrupt_requested())) {
    ShearPoint point;
    point.plan = plan;
    point.interrupted = true;
    point.failure = "interrupted before it started";
    return point;
  }
  return run_shear_rate(model, cell, engine, settings, plan, rate_index, hooks);
}

}  // namespace

std::vector<ShearPoint> run_shear_sweep(const membrane::MembraneModel& model,
                                        const mesh::TriangleMesh& cell, const ShearEngine& engine,
                                        const ShearSettings& settings,
                                        const std::vector<ShearRatePlan>& plans, int rate_threads,
                                        const ShearHooks& hooks) {
  std::vector<ShearPoint> points(plans.size());
  const auto count = static_cast<int>(plans.size());
  // Across processes the rates take turns: their steps talk to the other processes, from the main
  // thread only (parallel/communicator.hpp); the threads then go to each step's kernels.
  if (rate_threads <= 1 || count <= 1 || engine.coupling.processes.size() > 1) {
    for (std::size_t i = 0; i < plans.size(); ++i) {
      points[i] = sweep_rate(model, cell, engine, settings, plans[i], i, hooks);
    }
    return points;
  }
  // One rate per thread, each simulation on one thread; an input or logic error of any rate is
  // rethrown once all have ended.
  std::vector<std::exception_ptr> errors(plans.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::min(rate_threads, count))
  for (int i = 0; i < count; ++i) {
    const ThreadCountScope one_thread(1);
    const auto index = static_cast<std::size_t>(i);
    try {
      points[index] = sweep_rate(model, cell, engine, settings, plans[index], index, hooks);
    } catch (...) {
      errors[index] = std::current_exception();
    }
  }
  for (const auto& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  return points;
}

}  // namespace rbcsim::cases
