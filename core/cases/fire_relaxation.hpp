// FIRE, the Fast Inertial Relaxation Engine (Bitzek, Koskinen, Gaehler, Moseler, Gumbsch, PRL 97,
// 170201, 2006; with the semi-implicit Euler step and the half-step correction of FIRE 2.0,
// Guenole et al., Comput. Mater. Sci. 175, 109584, 2020): damped inertial dynamics that find the
// membrane's equilibrium under external forces in O(sqrt(stiff/soft)) iterations, where explicit
// overdamped Euler (membrane/relaxation.hpp) needs O(stiff/soft).
//
// It finds the same state as relax_membrane (all vertex forces below the tolerance), not a
// trajectory: the quasi-static stretch only asks for equilibria. Unit fictitious mass per
// vertex; the time step scales with the stiffest mode lambda_max (estimated as for Euler and
// refreshed every stiffness_update_interval iterations): dt_max = 1 / sqrt(lambda_max), half of
// the stability limit 2 / sqrt(lambda_max) of the inertial step.
#pragma once

#include <span>

#include "common/vec3.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/relaxation.hpp"

namespace rbcsim::cases {

// Same contract as membrane::relax_membrane: moves positions_um in place; converged is false
// when max_iterations came first; simulated_time_s is FIRE's fictitious time (no physics);
// mobility and step_fraction of the settings are not used. Throws RuntimeFailure when a term
// reaches its singular limit or a force is not finite.
membrane::RelaxationResult relax_membrane_fire(const membrane::MembraneModel& model,
                                               std::span<Vec3> positions_um,
                                               std::span<const Vec3> external_forces_pN,
                                               const membrane::RelaxationSettings& settings);

}  // namespace rbcsim::cases
