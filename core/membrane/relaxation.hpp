// Overdamped relaxation of one membrane without fluid: dx/dt = mobility * (F_membrane +
// F_external), integrated with explicit Euler. Used for the quasi-static stretch mode and shape
// checks.
//
// Step: explicit Euler on dx/dt = mobility F is stable while dt * mobility * lambda < 2 for every
// mode, lambda the stiffness (pN/um) of the mode. The stiffest mode is estimated by power iteration
// on the force Jacobian (finite differences of the total membrane force), so every enabled term,
// its tau divergence at the current deformation and the `paper` non-gradient forces are all
// covered without a per-term formula; dt = step_fraction / (mobility * lambda_max). The estimate
// is refreshed every stiffness_update_interval steps, as the tau terms stiffen with deformation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/membrane_model.hpp"

namespace rbcsim::membrane {

struct RelaxationSettings {
  double mobility_um_per_s_per_pN = 1.0;
  // Converged when the largest vertex force (membrane + external) is below this, i.e. the
  // largest vertex speed below mobility * force_tolerance_pN.
  double force_tolerance_pN = 1e-3;
  std::size_t max_iterations = 100000;
  // dt in units of 1 / (mobility * lambda_max); stable below 2, 1 damps the stiffest mode in one
  // step.
  double step_fraction = 1.0;
  std::size_t stiffness_update_interval = 1000;
  // Groups of vertices held together as one rigid body that only translates (the membrane glued
  // to a bead over its contact patch). Each member is driven by its group's mean net force (equal
  // masses, resp. mobilities), so the group keeps its shape; its equilibrium is a vanishing sum.
  std::vector<std::vector<std::int32_t>> rigid_groups{};
};

struct RelaxationResult {
  bool converged = false;  // false: max_iterations reached first (a failure the caller reports)
  std::size_t iterations = 0;
  double simulated_time_s = 0.0;
  double max_force_pN = 0.0;             // largest net vertex force at the end
  double stiffest_mode_pN_per_um = 0.0;  // last estimate of lambda_max
  double time_step_s = 0.0;              // last step
  std::size_t capped_vertex_count = 0;   // force-cap hits summed over all steps
};

// Moves positions_um (one per vertex) in place. external_forces_pN is empty or one per vertex.
// Throws RuntimeFailure when a term reaches its singular limit or a force is not finite, and
// Interrupted when a signal arrived (checked every iteration).
RelaxationResult relax_membrane(const MembraneModel& model, std::span<Vec3> positions_um,
                                std::span<const Vec3> external_forces_pN,
                                const RelaxationSettings& settings);

// Replaces the net force of every member of each group by the group's mean: the force that moves
// a rigid, translating group of equal masses as a whole (RelaxationSettings::rigid_groups).
void share_force_within_rigid_groups(std::span<const std::vector<std::int32_t>> groups,
                                     std::span<Vec3> net_forces_pN);

// lambda_max (pN/um): power iteration on the Jacobian of the total membrane force at positions_um.
double estimate_stiffest_mode_pN_per_um(const MembraneModel& model,
                                        std::span<const Vec3> positions_um);

}  // namespace rbcsim::membrane
