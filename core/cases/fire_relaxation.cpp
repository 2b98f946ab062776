#include "cases/fire_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cases/curvature_kinks.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"

namespace rbcsim::cases {
namespace {

// The standard FIRE parameters (Bitzek et al. 2006; alpha_start 0.25 and the smallest step of
// FIRE 2.0). They set the minimiser's speed, not the equilibrium it finds.
constexpr int kDelaySteps = 5;                  // N_min: downhill steps before speeding up
constexpr double kTimeStepIncrease = 1.1;       // f_inc
constexpr double kTimeStepDecrease = 0.5;       // f_dec
constexpr double kMixingStart = 0.25;           // alpha_start
constexpr double kMixingDecay = 0.99;           // f_alpha
constexpr double kStartStepFraction = 0.1;      // dt_start / dt_max
constexpr double kSmallestStepFraction = 0.02;  // dt_min / dt_max

double dot(std::span<const Vec3> a, std::span<const Vec3> b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i].dot(b[i]);
  return sum;
}

double max_norm(std::span<const Vec3> vectors) {
  double largest = 0.0;
  for (const auto& v : vectors) largest = std::max(largest, v.norm());
  return largest;
}

void check_arguments(const membrane::MembraneModel& model, std::span<Vec3> positions_um,
                     std::span<const Vec3> external_forces_pN,
                     const membrane::RelaxationSettings& settings) {
  const auto count = model.vertex_count();
  if (positions_um.size() != count ||
      (!external_forces_pN.empty() && external_forces_pN.size() != count)) {
    throw std::invalid_argument(
        "relax_membrane_fire: positions and external forces must have one entry per vertex");
  }
  if (settings.stiffness_update_interval == 0) {
    throw std::invalid_argument("relax_membrane_fire: needs stiffness_update_interval > 0");
  }
}

// The FIRE state between iterations: velocities, step, mixing and the downhill streak.
class FireState {
 public:
  explicit FireState(std::size_t vertex_count) : velocities_(vertex_count, Vec3::Zero()) {}

  double time_step() const { return time_step_; }

  // dt_max = 1 / sqrt(lambda_max): half the stability limit of the unit-mass inertial step.
  void rescale(double stiffest_mode_pN_per_um) {
    const double previous_largest = largest_time_step_;
    largest_time_step_ = 1.0 / std::sqrt(stiffest_mode_pN_per_um);
    time_step_ =
        previous_largest > 0.0
            ? std::min(time_step_ * largest_time_step_ / previous_largest, largest_time_step_)
            : kStartStepFraction * largest_time_step_;
  }

  // Power P = F.v > 0: keep going, and speed up after a streak. Otherwise step back half a step
  // (FIRE 2.0), stop and slow down.
  void adapt(std::span<const Vec3> forces, std::span<Vec3> positions) {
    if (dot(forces, velocities_) > 0.0) {
      if (++downhill_steps_ > kDelaySteps) {
        time_step_ = std::min(time_step_ * kTimeStepIncrease, largest_time_step_);
        mixing_ *= kMixingDecay;
      }
      return;
    }
    downhill_steps_ = 0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      positions[i] -= 0.5 * time_step_ * velocities_[i];
      velocities_[i] = Vec3::Zero();
    }
    time_step_ =
        std::max(time_step_ * kTimeStepDecrease, kSmallestStepFraction * largest_time_step_);
    mixing_ = kMixingStart;
  }

  // After a step that reached a force law's singular limit (an inertial overshoot, not the
  // equilibrium): back to the positions before it, at rest, with half the step. False when the
  // step is already the smallest: then the limit is real.
  bool retreat(std::span<const Vec3> previous, std::span<Vec3> positions) {
    if (time_step_ <= kSmallestStepFraction * largest_time_step_) return false;
    std::copy(previous.begin(), previous.end(), positions.begin());
    std::fill(velocities_.begin(), velocities_.end(), Vec3::Zero());
    time_step_ =
        std::max(time_step_ * kTimeStepDecrease, kSmallestStepFraction * largest_time_step_);
    mixing_ = kMixingStart;
    downhill_steps_ = 0;
    return true;
  }

  // Semi-implicit Euler with unit mass, the velocity turned towards the force by the mixing.
  void step(std::span<const Vec3> forces, std::span<Vec3> positions) {
    for (std::size_t i = 0; i < positions.size(); ++i) velocities_[i] += time_step_ * forces[i];
    const double force_norm = std::sqrt(dot(forces, forces));
    const double velocity_norm = std::sqrt(dot(velocities_, velocities_));
    const double steer = force_norm > 0.0 ? mixing_ * velocity_norm / force_norm : 0.0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      velocities_[i] = (1.0 - mixing_) * velocities_[i] + steer * forces[i];
      positions[i] += time_step_ * velocities_[i];
    }
  }

 private:
  std::vector<Vec3> velocities_;
  double time_step_ = 0.0;
  double largest_time_step_ = 0.0;
  double mixing_ = kMixingStart;
  int downhill_steps_ = 0;
};

}  // namespace

membrane::RelaxationResult relax_membrane_fire(const membrane::MembraneModel& model,
                                               std::span<Vec3> positions_um,
                                               std::span<const Vec3> external_forces_pN,
                                               const membrane::RelaxationSettings& settings) {
  check_arguments(model, positions_um, external_forces_pN, settings);
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  const CurvatureKinks kinks(model);
  FireState fire(model.vertex_count());
  std::vector<Vec3> net_pN(model.vertex_count());
  std::vector<Vec3> previous_um(positions_um.begin(), positions_um.end());
  membrane::RelaxationResult result;
  bool stiffness_outdated = false;
  for (result.iterations = 0;; ++result.iterations) {
    throw_if_interrupted();
    if (result.iterations % settings.stiffness_update_interval == 0 || stiffness_outdated) {
      stiffness_outdated = false;
      result.stiffest_mode_pN_per_um =
          membrane::estimate_stiffest_mode_pN_per_um(model, positions_um);
      fire.rescale(result.stiffest_mode_pN_per_um);
    }
    try {
      model.compute(positions_um, workspace, forces, membrane::ForceDetail::totals);
    } catch (const RuntimeFailure&) {
      if (!fire.retreat(previous_um, positions_um)) throw;
      stiffness_outdated = true;  // near a singular limit the stiffness grows without bound
      continue;
    }
    result.capped_vertex_count += forces.capped_vertex_count;
    for (std::size_t i = 0; i < net_pN.size(); ++i) {
      net_pN[i] = forces.total_pN[i] +
                  (external_forces_pN.empty() ? Vec3::Zero() : Vec3(external_forces_pN[i]));
    }
    kinks.smooth(positions_um, forces, net_pN);
    membrane::share_force_within_rigid_groups(settings.rigid_groups, net_pN);
    result.max_force_pN = max_norm(net_pN);
    result.converged = result.max_force_pN < settings.force_tolerance_pN;
    if (result.converged || result.iterations >= settings.max_iterations) break;
    std::copy(positions_um.begin(), positions_um.end(), previous_um.begin());
    fire.adapt(net_pN, positions_um);
    fire.step(net_pN, positions_um);
    result.simulated_time_s += fire.time_step();
  }
  result.time_step_s = fire.time_step();
  return result;
}

}  // namespace rbcsim::cases
