#include "minimise/fire.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "minimise/vector_field.hpp"

namespace rbcsim::minimise {
namespace {

// The standard FIRE parameters (Bitzek et al. 2006; alpha_start 0.25 and the smallest step of
// FIRE 2.0). They set the minimiser's speed, not the minimum it finds.
constexpr int kDelaySteps = 5;                  // N_min: downhill steps before speeding up
constexpr double kTimeStepIncrease = 1.1;       // f_inc
constexpr double kTimeStepDecrease = 0.5;       // f_dec
constexpr double kMixingStart = 0.25;           // alpha_start
constexpr double kMixingDecay = 0.99;           // f_alpha
constexpr double kStartStepFraction = 0.1;      // dt_start / dt_max
constexpr double kSmallestStepFraction = 0.02;  // dt_min / dt_max

// The FIRE state between iterations: velocities, step, mixing and the downhill streak.
class FireState {
 public:
  explicit FireState(std::size_t point_count) : velocities_(point_count, Vec3::Zero()) {}

  double time_step() const { return time_step_; }

  // dt_max = 1 / sqrt(lambda_max): half the stability limit of the unit-mass inertial step.
  void rescale(double stiffest_mode) {
    const double previous_largest = largest_time_step_;
    largest_time_step_ = 1.0 / std::sqrt(stiffest_mode);
    time_step_ =
        previous_largest > 0.0
            ? std::min(time_step_ * largest_time_step_ / previous_largest, largest_time_step_)
            : kStartStepFraction * largest_time_step_;
  }

  // Power P = F.v > 0: keep going, and speed up after a streak. Otherwise step back half a step
  // (FIRE 2.0), stop and slow down.
  void adapt(std::span<const Vec3> forces, std::span<Vec3> positions, FireProblem& problem) {
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
    problem.restore(positions);
    time_step_ =
        std::max(time_step_ * kTimeStepDecrease, kSmallestStepFraction * largest_time_step_);
    mixing_ = kMixingStart;
  }

  // After a step that reached a singular limit (an inertial overshoot, not the minimum): back to
  // the positions before it, at rest, with half the step. False when the step is already the
  // smallest: then the limit is real.
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

  // Semi-implicit Euler with unit mass, the velocity turned towards the force by the mixing,
  // kept tangent to the held constraints, which are restored after the move.
  void step(std::span<const Vec3> forces, std::span<Vec3> positions, FireProblem& problem) {
    for (std::size_t i = 0; i < positions.size(); ++i) velocities_[i] += time_step_ * forces[i];
    const double force_norm = std::sqrt(dot(forces, forces));
    const double velocity_norm = std::sqrt(dot(velocities_, velocities_));
    const double steer = force_norm > 0.0 ? mixing_ * velocity_norm / force_norm : 0.0;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      velocities_[i] = (1.0 - mixing_) * velocities_[i] + steer * forces[i];
    }
    problem.project(positions, velocities_);
    for (std::size_t i = 0; i < positions.size(); ++i) positions[i] += time_step_ * velocities_[i];
    problem.restore(positions);
  }

 private:
  std::vector<Vec3> velocities_;
  double time_step_ = 0.0;
  double largest_time_step_ = 0.0;
  double mixing_ = kMixingStart;
  int downhill_steps_ = 0;
};

}  // namespace

FireResult minimise_fire(FireProblem& problem, std::span<Vec3> positions,
                         const FireSettings& settings) {
  FireState fire(positions.size());
  std::vector<Vec3> net(positions.size());
  std::vector<Vec3> previous(positions.begin(), positions.end());
  FireResult result;
  bool stiffness_outdated = false;
  const std::size_t interval = std::max<std::size_t>(settings.stiffness_update_interval, 1);
  for (result.iterations = 0;; ++result.iterations) {
    throw_if_interrupted();
    if (result.iterations % interval == 0 || stiffness_outdated) {
      stiffness_outdated = false;
      result.stiffest_mode = problem.stiffest_mode(positions);
      fire.rescale(result.stiffest_mode);
    }
    try {
      problem.forces(positions, net);
    } catch (const RuntimeFailure&) {
      if (!fire.retreat(previous, positions)) throw;
      ++result.retreats;
      stiffness_outdated = true;  // near a singular limit the stiffness grows without bound
      continue;
    }
    result.max_force = max_norm(net);
    result.converged = result.max_force < settings.force_tolerance;
    result.time_step = fire.time_step();
    if (settings.on_iteration && !settings.on_iteration(result)) {
      result.converged = false;
      break;
    }
    if (result.converged || result.iterations >= settings.max_iterations) break;
    std::copy(positions.begin(), positions.end(), previous.begin());
    try {
      fire.adapt(net, positions, problem);
      fire.step(net, positions, problem);
    } catch (const RuntimeFailure&) {
      // A step the held constraints cannot be restored after: too long for their curvature.
      if (!fire.retreat(previous, positions)) throw;
      ++result.retreats;
      stiffness_outdated = true;
      continue;
    }
    result.simulated_time += fire.time_step();
  }
  result.time_step = fire.time_step();
  return result;
}

}  // namespace rbcsim::minimise
