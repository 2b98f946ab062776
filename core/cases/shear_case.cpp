#include "cases/shear_case.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <span>

#include "cases/named_table.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/state_archive.hpp"
#include "common/thread_count_scope.hpp"
#include "coupling/stop_criteria.hpp"
#include "membrane/cell_geometry.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::cases {
namespace {

// The symmetry axis counts as z when the least-variance principal axis is this close to it: a
// generated shape has it on z up to round-off, a mesh that does not is aligned first.
constexpr double kSymmetryAxisCosineTolerance = 1e-6;
// Tank-treading samples per check interval: the tracked point must turn by less than pi between
// two samples (a tank-treading membrane turns at about rate / 2, 0.5 rad per unit strain; the
// tips of an elongated cell faster).
constexpr double kPhaseSamplesPerCheck = 4.0;

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
  return find_named(std::span<const ShearBoundary>(kBoundaries), name, "shear.boundary",
                    "shear boundary");
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

// Stops when every criterion holds at the same step; remembers that it did.
class AllOf final : public coupling::StopCriterion {
 public:
  explicit AllOf(std::vector<std::unique_ptr<coupling::StopCriterion>> criteria, bool& held)
      : criteria_(std::move(criteria)), held_(held) {}
  std::optional<std::string> check(const coupling::CoupledSimulation& simulation) override {
    std::string reasons;
    bool all = true;
    for (auto& criterion : criteria_) {  // every one, every step: each keeps its own history
      const auto reason = criterion->check(simulation);
      all = all && reason.has_value();
      if (reason) reasons.append(reasons.empty() ? "" : "; ").append(*reason);
    }
    if (!all) return std::nullopt;
    held_ = true;
    return reasons;
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    for (std::size_t i = 0; i < criteria_.size(); ++i) {
      criteria_[i]->save_state(archive, prefix + std::to_string(i) + ".");
    }
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    for (std::size_t i = 0; i < criteria_.size(); ++i) {
      criteria_[i]->restore_state(archive, prefix + std::to_string(i) + ".");
    }
  }

 private:
  std::vector<std::unique_ptr<coupling::StopCriterion>> criteria_;
  bool& held_;
};

std::vector<Vec3> positions_now_um(const coupling::CoupledSimulation& simulation) {
  std::vector<Vec3> positions;
  for (const Vec3& p : simulation.cell(0).positions_lu()) {
    positions.push_back(simulation.frame().to_um(p));
  }
  return positions;
}

std::unique_ptr<coupling::StopCriterion> steady_shape(double rate_per_s,
                                                      const ShearSettings& settings, bool& held) {
  const coupling::SteadyStateTolerance tolerance{
      .relative_rate_per_s = settings.steady_tolerance_per_strain * rate_per_s,
      .check_interval_s = settings.check_interval_strain / rate_per_s};
  std::vector<std::unique_ptr<coupling::StopCriterion>> criteria;
  criteria.push_back(coupling::stop_at_steady_state(
      "the length",
      [](const coupling::CoupledSimulation& s) {
        return largest_vertex_distance_um(positions_now_um(s));
      },
      tolerance));
  criteria.push_back(coupling::stop_at_steady_state(
      "the breadth",
      [](const coupling::CoupledSimulation& s) {
        return measure_shear_shape(positions_now_um(s)).breadth_um;
      },
      tolerance));
  return std::make_unique<AllOf>(std::move(criteria), held);
}

// The unwrapped angle of one membrane point about the cell's centroid, sampled every
// interval_steps steps.
class PhaseRecorder {
 public:
  PhaseRecorder(std::size_t vertex, std::size_t interval_steps)
      : vertex_(vertex), interval_steps_(interval_steps) {}
  void operator()(const coupling::CoupledSimulation& simulation) {
    const auto& cell = simulation.cell(0);
    const double angle = in_plane_angle_rad(cell.positions_lu()[vertex_], cell.centroid_lu());
    angles_rad_.push_back(angles_rad_.empty() ? angle
                                              : unwrap_angle_rad(angles_rad_.back(), angle));
    times_s_.push_back(simulation.time_s());
    steps_.push_back(static_cast<double>(simulation.time_step()));
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
  // The samples taken on their interval: an interrupted run's observers also see the state
  // reached between two intervals, which a straight run never samples.
  void save_state(StateArchive& archive, const std::string& prefix) const {
    std::vector<double> steps, times_s, angles_rad;
    for (std::size_t i = 0; i < steps_.size(); ++i) {
      if (static_cast<std::size_t>(steps_[i]) % interval_steps_ != 0) continue;
      steps.push_back(steps_[i]);
      times_s.push_back(times_s_[i]);
      angles_rad.push_back(angles_rad_[i]);
    }
    archive.put(prefix + "steps", std::move(steps));
    archive.put(prefix + "times_s", std::move(times_s));
    archive.put(prefix + "angles_rad", std::move(angles_rad));
  }
  void restore_state(StateArchive& archive, const std::string& prefix) {
    steps_ = archive.take(prefix + "steps", std::nullopt);
    times_s_ = archive.take(prefix + "times_s", steps_.size());
    angles_rad_ = archive.take(prefix + "angles_rad", steps_.size());
  }

 private:
  std::size_t vertex_;
  std::size_t interval_steps_;
  std::vector<double> steps_;
  std::vector<double> times_s_;
  std::vector<double> angles_rad_;
};

// Never stops the run: carries the tank-treading record in the checkpoint.
class PhaseInCheckpoint final : public coupling::StopCriterion {
 public:
  explicit PhaseInCheckpoint(std::shared_ptr<PhaseRecorder> phase) : phase_(std::move(phase)) {}
  std::optional<std::string> check(const coupling::CoupledSimulation& /*simulation*/) override {
    return std::nullopt;
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    phase_->save_state(archive, prefix);
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    phase_->restore_state(archive, prefix);
  }

 private:
  std::shared_ptr<PhaseRecorder> phase_;
};

// The vertex farthest along +x: on the rim of a cell whose axis is y, in the shear plane.
std::size_t tracked_vertex(const mesh::TriangleMesh& cell) {
  const auto& p = cell.positions_um;
  return static_cast<std::size_t>(
      std::max_element(p.begin(), p.end(),
                       [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); }) -
      p.begin());
}

// The smoothness and roughness of the cell's surface now (shear_observables.hpp).
void measure_surface(const membrane::MembraneModel& model, std::span<const Vec3> positions_um,
                     ShearPoint& point) {
  membrane::CellGeometry geometry(model.topology().triangle_count(), model.topology().edge_count());
  membrane::measure_cell_geometry(positions_um, model.triangles(), model.topology(), geometry);
  const auto& reference_rad = model.reference().dihedral_angles_rad;
  point.smoothness_rad = dihedral_change_rms_rad(geometry.dihedral_angles_rad, reference_rad);
  point.roughness_rad =
      dihedral_roughness_rad(geometry.dihedral_angles_rad, reference_rad, model.topology());
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
  return names_of(std::span<const ShearBoundary>(kBoundaries));
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
  const auto started = std::chrono::steady_clock::now();
  const double dx_um = engine.lattice.spacing_um;
  const ShearBox box = shear_box(cell, dx_um, settings);
  const auto units = simulated_units(engine, plan);
  const double flow_rate_lu = plan.shear_rate_per_s > 0.0 ? plan.strain_rate_lu : 0.0;
  auto coupling = engine.coupling;
  if (!coupling.run_directory.empty()) coupling.run_directory /= shear_rate_directory(rate_index);

  coupling::CoupledSimulation simulation(
      shear_fluid(box, engine.fluid, settings.boundary, flow_rate_lu), units, coupling,
      box_origin_um(box, dx_um));
  simulation.add_cell(membrane::MembraneModel(cell, model.parameters()), cell.positions_um);
  const double time_unit_rate = plan.strain_rate_lu / units.dt_s();
  bool steady = false;
  simulation.add_stop_criterion(steady_shape(time_unit_rate, settings, steady));
  simulation.add_stop_criterion(coupling::stop_at_time(settings.max_strain / time_unit_rate));
  const auto phase_interval_steps =
      steps_for(settings.check_interval_strain / kPhaseSamplesPerCheck, plan.strain_rate_lu);
  auto phase = std::make_shared<PhaseRecorder>(tracked_vertex(cell), phase_interval_steps);
  simulation.add_observer({"tank_treading_point", phase_interval_steps,
                           [phase](const coupling::CoupledSimulation& s) { (*phase)(s); }});
  simulation.add_stop_criterion(std::make_unique<PhaseInCheckpoint>(phase));
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
  const auto positions_um = positions_now_um(simulation);
  point.shape = measure_shear_shape(positions_um);
  measure_surface(model, positions_um, point);
  point.tank_treading_hz = phase->frequency_hz() / plan.viscosity_scale;
  point.steps = simulation.time_step();
  point.strain = simulation.time_s() * time_unit_rate;
  point.time_s = simulation.time_s() * plan.viscosity_scale;
  point.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (point.failure.empty() && hooks.finished) hooks.finished(rate_index, point, simulation);
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
  if (interrupt_requested()) {
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
  if (rate_threads <= 1 || count <= 1) {
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
