// FIRE, the Fast Inertial Relaxation Engine (Bitzek, Koskinen, Gaehler, Moseler, Gumbsch, PRL 97,
// 170201, 2006; with the semi-implicit Euler step and the half-step correction of FIRE 2.0,
// Guenole et al., Comput. Mater. Sci. 175, 109584, 2020): damped inertial dynamics that find the
// membrane's equilibrium under external forces in O(sqrt(stiff/soft)) iterations, where explicit
// overdamped Euler (membrane/relaxation.hpp) needs O(stiff/soft): 240 against 6570 iterations
// for the N = 3 discocyte at 10 pN (tested).
//
// It finds a state, not a trajectory: the quasi-static stretch only asks for equilibria. Unit
// fictitious mass per vertex; the time step scales with the stiffest mode lambda_max (estimated
// as for Euler, refreshed every stiffness_update_interval iterations and after a retreat):
// dt_max = 1 / sqrt(lambda_max), half the stability limit of the inertial step.
//
// Two things differ from plain FIRE, both because of the membrane's force laws:
// - the total-curvature term's kinks are smoothed over a width eps (curvature_kinks.hpp), so the
//   equilibrium is an ordinary one and the force criterion can be met;
// - a step that takes a deviation to its singular limit tau (an inertial overshoot near a steep
//   log barrier, e.g. a triangle's area near +30 %) is undone: back to the previous positions, at
//   rest, with half the step and a fresh stiffness estimate. Only when the step is already the
//   smallest is the limit real, and the RuntimeFailure is passed on.
#pragma once

#include <span>

#include "common/vec3.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/relaxation.hpp"

namespace rbcsim::cases {

// Same contract as membrane::relax_membrane: moves positions_um in place; converged (the largest
// net vertex force of the smoothed model below force_tolerance_pN) is false when max_iterations
// came first; simulated_time_s is FIRE's fictitious time (no physics); mobility and
// step_fraction of the settings are not used. Throws RuntimeFailure when a term reaches its
// singular limit at the smallest step, or a force is not finite.
membrane::RelaxationResult relax_membrane_fire(const membrane::MembraneModel& model,
                                               std::span<Vec3> positions_um,
                                               std::span<const Vec3> external_forces_pN,
                                               const membrane::RelaxationSettings& settings);

}  // namespace rbcsim::cases
