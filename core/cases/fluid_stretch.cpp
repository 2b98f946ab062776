#include "cases/fluid_stretch.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/curvature_kinks.hpp"
#include "cases/relaxation_methods.hpp"
#include "cases/stretch_geometry.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/state_archive.hpp"
#include "common/wall_clock.hpp"
#include "coupling/snapshot.hpp"

namespace rbcsim::cases {
namespace {

using coupling::CoupledSimulation;

// The lattice speed of sound, 1/sqrt(3): Mach = u / c_s.
const double kLatticeSoundSpeed = 1.0 / std::sqrt(3.0);

// One force's stop: both diameters steady, or the force's time is up. Restarted at every force,
// so that one criterion serves the whole curve of one simulation; its deadline and the
// steady-state checks ride in the checkpoint.
class ForceStop final : public coupling::StopCriterion {
 public:
  explicit ForceStop(const FluidStretchSettings& settings) : settings_(settings) { start(0.0); }

  void start(double now_s) {
    deadline_s_ = now_s + settings_.max_time_per_force_s;
    axial_ = coupling::stop_at_steady_state(
        "the axial diameter",
        [](const CoupledSimulation& s) { return axial_diameter_um(s.positions_now_um(0)); },
        settings_.steady);
    transverse_ = coupling::stop_at_steady_state(
        "the transverse diameter",
        [](const CoupledSimulation& s) { return transverse_diameter_um(s.positions_now_um(0)); },
        settings_.steady);
    steady_ = false;
  }

  std::optional<std::string> check(const CoupledSimulation& simulation) override {
    // Both are asked every step: each keeps its own record of checks.
    const auto axial = axial_->check(simulation);
    const auto transverse = transverse_->check(simulation);
    if (axial && transverse) {
      steady_ = true;
      return *axial + "; " + *transverse;
    }
    // The relative slack absorbs the round-off of steps * dt against a time in seconds.
    if (simulation.time_s() < deadline_s_ * (1.0 - 1e-12)) return std::nullopt;
    return "not steady after " + format_number(settings_.max_time_per_force_s) + " s";
  }

  // A checkpoint is taken while a force runs (never once it has stopped): steady_ is false.
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put(prefix + "deadline_s", {deadline_s_});
    axial_->save_state(archive, prefix + "axial.");
    transverse_->save_state(archive, prefix + "transverse.");
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    deadline_s_ = archive.take_number(prefix + "deadline_s");
    axial_->restore_state(archive, prefix + "axial.");
    transverse_->restore_state(archive, prefix + "transverse.");
  }

  bool steady() const { return steady_; }

 private:
  const FluidStretchSettings& settings_;
  double deadline_s_ = 0.0;
  std::unique_ptr<coupling::StopCriterion> axial_;
  std::unique_ptr<coupling::StopCriterion> transverse_;
  bool steady_ = false;
};

// The tweezers' force moving linearly from one value to the next.
struct ForceRamp {
  double from_pN = 0.0;
  double to_pN = 0.0;
  double start_s = 0.0;

  double force_pN(double now_s, double ramp_time_s) const {
    const double progress = ramp_time_s > 0.0 ? (now_s - start_s) / ramp_time_s : 1.0;
    return from_pN + (to_pN - from_pN) * std::clamp(progress, 0.0, 1.0);
  }
};

std::unique_ptr<CoupledSimulation> make_simulation(const membrane::MembraneModel& model,
                                                   const StretchCell& cell,
                                                   const FluidStretchSettings& settings) {
  const units::UnitConverter units(settings.lattice);
  const auto box =
      stretch_box(cell.mesh.positions_um, settings.lattice.spacing_um, settings.box_margin_um);
  auto fluid = std::make_unique<lattice::FluidSolver>(
      lattice::LatticeGrid(box.nodes[0], box.nodes[1], box.nodes[2]), settings.fluid);
  auto parameters = settings.coupling;
  parameters.run_directory = settings.output_directory;
  auto simulation = std::make_unique<CoupledSimulation>(std::move(fluid), units,
                                                        std::move(parameters), box.origin_um);
  simulation->add_cell(membrane::MembraneModel(cell.mesh, model.reference(), model.parameters()),
                       cell.mesh.positions_um);
  return simulation;
}

double largest_norm(std::span<const Vec3> vectors) {
  double largest = 0.0;
  for (const Vec3& v : vectors) largest = std::max(largest, v.norm());
  return largest;
}

// Where a force's run started, and the largest vertex speed (lattice units) since.
struct ForceRunStart {
  std::size_t step = 0;
  std::size_t capped_steps = 0;
  double max_speed_lu = 0.0;
  WallClock::time_point wall_clock = WallClock::now();
};

// Where the curve is: with the simulation's own state, what a resumed run continues from.
struct CurveProgress {
  std::size_t force_index = 0;  // the force being applied
  bool force_started = false;   // its ramp, stop criterion and start record are set
  ForceRamp ramp;
  ForceRunStart start;
  std::size_t warm_start_iterations = 0;  // of this force's warm start (0: ramped)
  WarmStart warm_start = WarmStart::off;  // how this force started
  std::vector<StretchPoint> points;  // of the forces before force_index
};

// A point as numbers, in this order, for the checkpoint; the force record likewise.
constexpr std::size_t kPointValues = 12;
constexpr std::size_t kForceValues = 10;

std::vector<double> point_values(std::span<const StretchPoint> points) {
  std::vector<double> values;
  values.reserve(points.size() * kPointValues);
  for (const auto& p : points) {
    values.insert(values.end(),
                  {p.force_pN, p.axial_um, p.transverse_um, p.converged ? 1.0 : 0.0,
                   static_cast<double>(p.iterations), static_cast<double>(p.steps), p.time_s,
                   p.max_mach_number, p.max_reynolds_number, p.residual_force_pN,
                   static_cast<double>(p.force_cap_hits), p.wall_time_s});
  }
  return values;
}

std::vector<StretchPoint> points_from(std::span<const double> values) {
  std::vector<StretchPoint> points;
  for (std::size_t i = 0; i + kPointValues <= values.size(); i += kPointValues) {
    const auto v = values.subspan(i, kPointValues);
    points.push_back({.force_pN = v[0],
                      .axial_um = v[1],
                      .transverse_um = v[2],
                      .converged = v[3] != 0.0,
                      .iterations = static_cast<std::size_t>(v[4]),
                      .steps = static_cast<std::size_t>(v[5]),
                      .time_s = v[6],
                      .max_mach_number = v[7],
                      .max_reynolds_number = v[8],
                      .residual_force_pN = v[9],
                      .force_cap_hits = static_cast<std::size_t>(v[10]),
                      .wall_time_s = v[11]});
  }
  return points;
}

// Never stops the run: carries the curve's progress in the checkpoint (as shear's tank-treading
// record rides in its). A force's wall time goes on from where the checkpoint left it.
class ProgressInCheckpoint final : public coupling::StopCriterion {
 public:
  explicit ProgressInCheckpoint(CurveProgress& progress) : progress_(progress) {}
  std::optional<std::string> check(const CoupledSimulation& /*simulation*/) override {
    return std::nullopt;
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    const auto& p = progress_;
    const double wall_s = seconds_since(p.start.wall_clock);
    archive.put(prefix + "force",
                {static_cast<double>(p.force_index), p.force_started ? 1.0 : 0.0, p.ramp.from_pN,
                 p.ramp.to_pN, p.ramp.start_s, static_cast<double>(p.start.step),
                 static_cast<double>(p.start.capped_steps), p.start.max_speed_lu, wall_s,
                 static_cast<double>(p.warm_start_iterations)});
    archive.put(prefix + "points", point_values(p.points));
    // How each force started: this one's, then each point's.
    std::vector<double> starts{static_cast<double>(p.warm_start)};
    for (const auto& point : p.points) starts.push_back(static_cast<double>(point.warm_start));
    archive.put(prefix + "warm_starts", std::move(starts));
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    const auto force = archive.take(prefix + "force", kForceValues);
    auto& p = progress_;
    p.force_index = static_cast<std::size_t>(force[0]);
    p.force_started = force[1] != 0.0;
    p.ramp = {force[2], force[3], force[4]};
    p.start.step = static_cast<std::size_t>(force[5]);
    p.start.capped_steps = static_cast<std::size_t>(force[6]);
    p.start.max_speed_lu = force[7];
    p.start.wall_clock = started_seconds_ago(force[8]);
    p.warm_start_iterations = static_cast<std::size_t>(force[9]);
    const auto values = archive.take(prefix + "points", std::nullopt);
    if (values.size() % kPointValues != 0) {
      throw InputError(archive.source(), prefix + "points: not whole points");
    }
    p.points = points_from(values);
    const auto starts = archive.take(prefix + "warm_starts", p.points.size() + 1);
    const auto start_of = [](double value) {
      return static_cast<WarmStart>(static_cast<int>(value));
    };
    p.warm_start = start_of(starts[0]);
    for (std::size_t i = 0; i < p.points.size(); ++i)
      p.points[i].warm_start = start_of(starts[i + 1]);
  }

 private:
  CurveProgress& progress_;
};

// The observables of the state reached and what it took to reach it.
void measure_point(const CoupledSimulation& simulation, std::span<const Vec3> positions_um,
                   const ForceRunStart& start, StretchPoint& point) {
  const auto& units = simulation.units();
  point.steps = simulation.time_step() - start.step;
  point.time_s = units.to_physical(units::PhysicalUnit::time_s, static_cast<double>(point.steps));
  point.axial_um = axial_diameter_um(positions_um);
  point.transverse_um = transverse_diameter_um(positions_um);
  point.residual_force_pN = largest_norm(simulation.cell(0).total_forces_pN());
  point.force_cap_hits = simulation.capped_steps_per_cell().front() - start.capped_steps;
  point.max_mach_number = start.max_speed_lu / kLatticeSoundSpeed;
  const double viscosity_m2_per_s = units.to_physical(
      units::PhysicalUnit::kinematic_viscosity_m2_per_s, units.lattice_kinematic_viscosity());
  point.max_reynolds_number =
      units.to_physical(units::PhysicalUnit::velocity_m_per_s, start.max_speed_lu) *
      point.axial_um * 1e-6 / viscosity_m2_per_s;
}

std::string not_steady(std::span<const StretchPoint> points, double max_time_s) {
  std::string forces;
  for (const auto& point : points) {
    if (point.converged) continue;
    forces += (forces.empty() ? "" : ", ") + format_number(point.force_pN);
  }
  if (forces.empty()) return {};
  return "F = " + forces + " pN: the diameters were not steady after " + format_number(max_time_s) +
         " s; raise stretch.fluid.max_time_per_force_s or loosen stretch.fluid.steady_*";
}

// stretch.fluid.warm_start: the membrane's equilibrium under force_pN from the shape reached
// (the quasi-static relaxation, the same model and tweezers), put in place at rest, with its
// iterations; or, when it did not converge or met a force law's limit on the way, which of the
// two (the shape left as it was: the force is then ramped).
struct WarmStartResult {
  WarmStart outcome = WarmStart::off;
  std::size_t iterations = 0;
};

WarmStartResult warm_start(CoupledSimulation& simulation, const StretchCell& cell,
                           const StretchSettings& settings, double force_pN) {
  const auto& model = simulation.cell(0).model();
  auto positions_um = simulation.positions_now_um(0);
  const auto tweezers_pN = tweezer_forces_pN(model.vertex_count(), cell.patches, force_pN);
  const auto relax = find_relaxation_method(settings.relaxation);
  try {
    const auto result = relax(model, positions_um, tweezers_pN, settings.relaxation_settings);
    if (!result.converged) return {WarmStart::not_converged, result.iterations};
    simulation.move_cell(0, positions_um);
    return {WarmStart::converged, result.iterations};
  } catch (const RuntimeFailure&) {
    return {WarmStart::force_law_limit, 0};
  }
}

// The next force: the tweezers ramp to it from the force they reached (or stand at it, from a
// warm start), its stop criterion and start record begin now.
void start_force(const CoupledSimulation& simulation, double force_pN, double ramp_time_s,
                 const WarmStartResult& warm, ForceStop& force_stop, CurveProgress& progress) {
  const double now_s = simulation.time_s();
  const bool warm_started = warm.outcome == WarmStart::converged;
  const double from_pN = warm_started ? force_pN : progress.ramp.force_pN(now_s, ramp_time_s);
  progress.ramp = {from_pN, force_pN, now_s};
  progress.warm_start_iterations = warm_started ? warm.iterations : 0;
  progress.warm_start = warm.outcome;
  progress.start = {.step = simulation.time_step(),
                    .capped_steps = simulation.capped_steps_per_cell().front()};
  force_stop.start(now_s);
  progress.force_started = true;
}

}  // namespace

StretchBox stretch_box(std::span<const Vec3> positions_um, double dx_um, double margin_um) {
  Vec3 low = positions_um.front();
  Vec3 high = positions_um.front();
  for (const Vec3& p : positions_um) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  Vec3 extent_um = high - low;
  extent_um.x() *= 2.0;  // room for the cell at twice its rest length along the pull
  const Vec3 centre_um = 0.5 * (low + high);
  StretchBox box;
  for (int axis = 0; axis < 3; ++axis) {
    // Periodic: n nodes span n dx, so n = ceil(L / dx) leaves at least the margin.
    const double length_um = extent_um[axis] + 2.0 * margin_um;
    box.nodes[static_cast<std::size_t>(axis)] = static_cast<int>(std::ceil(length_um / dx_um));
    box.origin_um[axis] =
        centre_um[axis] - 0.5 * dx_um * (box.nodes[static_cast<std::size_t>(axis)] - 1);
  }
  return box;
}

StretchRun run_fluid_stretch(const membrane::MembraneModel& model, const StretchCell& cell,
                             const StretchSettings& settings, const StretchObserver& observer) {
  if (settings.contact.rigid) {
    throw InputError("stretch.contact.rigid",
                     "the fluid mode moves every vertex with the fluid and cannot hold a contact "
                     "patch rigid; use the quasi-static mode or set it to false");
  }
  const auto& fluid_settings = settings.fluid;
  // Constructed in one place and run() called in one place (checkpointing wires in here).
  const auto simulation = make_simulation(model, cell, fluid_settings);
  // The tweezer forces are linear in F: those of 1 pN, scaled by the ramped force.
  const auto unit_tweezers_pN = tweezer_forces_pN(model.vertex_count(), cell.patches, 1.0);
  CurveProgress progress;
  // The total-curvature kinks smoothed as in the quasi-static mode (curvature_kinks.hpp): the
  // same model, and no force that flips sign with a flat edge's angle from one step to the next.
  const CurvatureKinks kinks(simulation->cell(0).model());
  simulation->add_external_force(
      [&](std::size_t, const coupling::Cell& state, std::span<Vec3> forces_pN) {
        const double force_pN =
            progress.ramp.force_pN(simulation->time_s(), fluid_settings.force_ramp_time_s);
        for (std::size_t v = 0; v < forces_pN.size(); ++v) {
          forces_pN[v] += force_pN * unit_tweezers_pN[v];
        }
        kinks.smooth(state.positions_um(), state.membrane_forces(), forces_pN);
      });
  simulation->add_observer({"stretch_speed", 1, [&progress](const CoupledSimulation& s) {
                              auto& max_speed_lu = progress.start.max_speed_lu;
                              max_speed_lu =
                                  std::max(max_speed_lu, largest_norm(s.cell(0).velocities_lu()));
                            }});
  auto stop = std::make_unique<ForceStop>(fluid_settings);
  ForceStop& force_stop = *stop;
  simulation->add_stop_criterion(std::move(stop));
  simulation->add_stop_criterion(std::make_unique<ProgressInCheckpoint>(progress));
  const auto& units = simulation->units();
  if (fluid_settings.snapshot_interval_s > 0.0 && !fluid_settings.output_directory.empty()) {
    const double steps =
        units.to_lattice(units::PhysicalUnit::time_s, fluid_settings.snapshot_interval_s);
    coupling::add_snapshot_output(*simulation, fluid_settings.output_directory,
                                  {static_cast<std::size_t>(std::max(1.0, std::round(steps))), 0,
                                   fluid_settings.snapshot_format});
  }
  if (fluid_settings.configure) fluid_settings.configure(*simulation);

  StretchRun run;
  run.sub_spacing_drag = simulation->sub_spacing_drag_summary();
  for (; progress.force_index < settings.forces_pN.size(); ++progress.force_index) {
    const double force_pN = settings.forces_pN[progress.force_index];
    if (!progress.force_started) {
      const auto warm = fluid_settings.warm_start
                            ? warm_start(*simulation, cell, settings, force_pN)
                            : WarmStartResult{};
      start_force(*simulation, force_pN, fluid_settings.force_ramp_time_s, warm, force_stop,
                  progress);
    }
    StretchPoint point{.force_pN = force_pN,
                       .iterations = progress.warm_start_iterations,
                       .warm_start = progress.warm_start};
    try {
      simulation->run();
      point.converged = force_stop.steady();
    } catch (const RuntimeFailure& failure) {
      run.failure = "F = " + format_number(force_pN) + " pN: " + failure.what();
    } catch (const Interrupted& interrupted) {  // the unfinished force is not a point
      run.failure = "F = " + format_number(force_pN) + " pN: " + interrupted.what();
      run.interrupted = true;
      break;
    }
    progress.force_started = false;
    point.wall_time_s = seconds_since(progress.start.wall_clock);
    const auto positions_um = simulation->positions_now_um(0);
    measure_point(*simulation, positions_um, progress.start, point);
    progress.points.push_back(point);
    if (observer) {
      // After a membrane failure its forces are those of a shape at a force law's limit: none.
      if (run.ok()) simulation->add_term_forces();
      const auto& state = simulation->cell(0);
      const auto tweezers_pN = tweezer_forces_pN(model.vertex_count(), cell.patches, force_pN);
      observer({progress.points.size() - 1, progress.points.back(), positions_um,
                run.ok() ? &state.membrane_forces() : nullptr, tweezers_pN});
    }
    if (!run.ok()) break;
  }
  run.points = std::move(progress.points);
  if (!run.ok()) return run;
  if (!fluid_settings.output_directory.empty()) {
    coupling::write_fluid_snapshot(fluid_settings.output_directory / "fluid.vti", *simulation);
  }
  run.failure = not_steady(run.points, fluid_settings.max_time_per_force_s);
  return run;
}

}  // namespace rbcsim::cases
