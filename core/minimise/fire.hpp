// FIRE, the Fast Inertial Relaxation Engine (Bitzek, Koskinen, Gaehler, Moseler, Gumbsch, PRL 97,
// 170201, 2006; with the semi-implicit Euler step and the half-step correction of FIRE 2.0,
// Guenole et al., Comput. Mater. Sci. 175, 109584, 2020): damped inertial dynamics of unit-mass
// points that find a minimum of an energy (a state where the net force vanishes) in
// O(sqrt(stiff/soft)) iterations, where overdamped explicit Euler needs O(stiff/soft).
//
// The one minimiser of rbcsim: the quasi-static stretch relaxes the six-force membrane with it
// (cases/fire_relaxation.hpp) and the shape generator minimises the bilayer-couple energy with it
// (core/shapes), each supplying a FireProblem. The time step scales with the stiffest mode
// lambda_max (estimated by the problem, refreshed every stiffness_update_interval iterations and
// after a retreat): dt_max = 1 / sqrt(lambda_max), half the stability limit of the inertial step.
//
// Two things beyond plain FIRE:
// - a step whose force evaluation throws RuntimeFailure (an inertial overshoot that took a force
//   law to its singular limit, e.g. a triangle's area near +30 %) is undone: back to the previous
//   positions, at rest, with half the step and a fresh stiffness estimate. Only when the step is
//   already the smallest is the failure real, and it is passed on;
// - held constraints (the problem's project/restore): the forces the problem returns are already
//   tangent to them; the velocities are projected before every move and the constraints restored
//   after it.
#pragma once

#include <cstddef>
#include <functional>
#include <span>

#include "common/vec3.hpp"

namespace rbcsim::minimise {

class FireProblem {
 public:
  virtual ~FireProblem() = default;
  // Overwrites `forces` with the net force at `positions` (minus the energy gradient, tangent to
  // any held constraint). May throw RuntimeFailure when `positions` reached a singular limit.
  virtual void forces(std::span<const Vec3> positions, std::span<Vec3> forces) = 0;
  // lambda_max of the force's Jacobian at `positions` (force per length per unit mass).
  virtual double stiffest_mode(std::span<const Vec3> positions) = 0;
  // Removes from `vectors` what would change a held constraint at `positions` (default: none).
  virtual void project(std::span<const Vec3> /*positions*/, std::span<Vec3> /*vectors*/) {}
  // Moves `positions` back onto the held constraints after a step (default: none).
  virtual void restore(std::span<Vec3> /*positions*/) {}
};

struct FireResult {
  bool converged = false;  // max_force < force_tolerance; false: max_iterations came first
  std::size_t iterations = 0;
  double max_force = 0.0;       // largest net force of a point at the end
  double simulated_time = 0.0;  // FIRE's fictitious time (no physics)
  double time_step = 0.0;       // the last step
  double stiffest_mode = 0.0;   // the last estimate of lambda_max
  std::size_t retreats = 0;     // steps undone after a singular limit
};

struct FireSettings {
  double force_tolerance = 1e-3;
  std::size_t max_iterations = 100000;
  std::size_t stiffness_update_interval = 1000;
  // Called after each iteration's force evaluation (progress, an interrupt check, or an extra
  // stop condition: return false to stop with converged = false). Empty: none.
  std::function<bool(const FireResult& so_far)> on_iteration;
};

// Moves `positions` in place towards a minimum. Throws what problem.forces throws when it throws
// at the smallest step, and Interrupted when a signal arrived (checked every iteration).
FireResult minimise_fire(FireProblem& problem, std::span<Vec3> positions,
                         const FireSettings& settings);

}  // namespace rbcsim::minimise
