// Membrane viscosity term (force_terms.hpp): the edge friction of edge_friction.hpp at the
// context's vertex velocities.
#include <algorithm>

#include "common/errors.hpp"
#include "membrane/force_terms.hpp"

namespace rbcsim::membrane {

ViscosityTerm::ViscosityTerm(const MembraneParameters& parameters)
    : friction_(edge_friction_for(parameters.viscosity_Pa_s_um, parameters.viscosity_split)) {
  if (!(parameters.viscosity_Pa_s_um >= 0.0)) {
    throw InputError("membrane.viscosity_Pa_s_um", "must be >= 0");
  }
}

void ViscosityTerm::evaluate(const TermContext& context, TermScratch&, TermForces& out) const {
  out.energy_pN_um = 0.0;
  out.max_abs_deviation = 0.0;
  if (context.velocities_um_per_s.empty()) {
    std::fill(out.forces_pN.begin(), out.forces_pN.end(), Vec3::Zero());
    return;
  }
  edge_friction_forces(context.positions_um, context.velocities_um_per_s,
                       EdgeNetwork::of(context.topology), friction_, out.forces_pN);
}

}  // namespace rbcsim::membrane
