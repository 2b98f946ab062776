// Volume force (Eq. 9, no linear term). Per cell, d = (V - V0)/V0 and E = K_v energy_v(d).
// Exact gradient: dV/dx_i = g_i = (1/3) sum over i's triangles of their area vectors (A_f n_f:
// "along the face normals weighted by face area"), so F_i = -(K_v / V0) slope_v(d) g_i.
// Scale: we want the mean force magnitude over the vertices at the reference geometry to be Eq. 9's
// (k_v kBT / L0) slope_v(d); with g0 = mean_i |g_i| at the reference,
//   K_v = (k_v kBT / L0) V0 / g0   and   F_i = -(k_v kBT / L0) slope_v(d) g_i / g0.
// Central in both distributions (sum_i g_i = 0 on a closed surface, and V is rotation invariant).
#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

VolumeTerm::VolumeTerm(const MembraneParameters& parameters)
    : LawTerm(ForceLaw::divergent_only(parameters.tau_volume), parameters.k_volume_kBT,
              parameters.force_length_scale_um, parameters.thermal_energy_pN_um) {}

void VolumeTerm::evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const {
  const auto& reference = context.reference;
  const double deviation =
      (context.geometry.volume_um3 - reference.volume_um3) / reference.volume_um3;
  require_within_limit("volume", "the cell", deviation, law_.tau());
  const double gradient_scale_um2 = reference.mean_volume_gradient_um2;
  out.energy_pN_um =
      force_scale_pN_ * reference.volume_um3 / gradient_scale_um2 * law_.energy(deviation);
  out.max_abs_deviation = std::abs(deviation);

  // Each triangle gives each of its corners a third of its area vector.
  const double coefficient_pN_per_um2 =
      -force_scale_pN_ * law_.slope(deviation) / (3.0 * gradient_scale_um2);
  const auto& area_vectors_um2 = context.geometry.triangle_area_vectors_um2;
  parallel_for(context.triangles.size(), [&](std::size_t t) {
    const Vec3 force_pN = coefficient_pN_per_um2 * area_vectors_um2[t];
    for (std::size_t k = 0; k < 3; ++k) scratch.slot_forces_pN[3 * t + k] = force_pN;
  });
  context.stencils.triangle.gather(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
