// The bilayer's local area (force_terms.hpp, LocalAreaTerm). Per triangle t, d = (A_t - A0_t)/A0_t
// and E_t = K A0_t d^2 / 2 = K (A_t - A0_t)^2 / (2 A0_t), so with the exact area gradient
// dA_t/dx_k = (1/2) n x (x_{k+2} - x_{k+1}) (area_term.cpp) the corner force is
// F_k = -K d (1/2) n x (x_{k+2} - x_{k+1}), pN with K in pN/um. Central, harmonic.
#include <cmath>
#include <span>

#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

LocalAreaTerm::LocalAreaTerm(const MembraneParameters& parameters)
    : modulus_pN_per_um_(parameters.local_area_modulus_uN_per_m) {}

void LocalAreaTerm::evaluate(const TermContext& context, TermScratch& scratch,
                             TermForces& out) const {
  const auto triangle_count = context.triangles.size();
  const auto& area_vectors_um2 = context.geometry.triangle_area_vectors_um2;
  const auto& reference_areas_um2 = context.reference.triangle_areas_um2;
  parallel_for(triangle_count, [&](std::size_t t) {
    const double deviation =
        (area_vectors_um2[t].norm() - reference_areas_um2[t]) / reference_areas_um2[t];
    scratch.deviations[t] = deviation;
    scratch.energies_pN_um[t] =
        0.5 * modulus_pN_per_um_ * reference_areas_um2[t] * deviation * deviation;
  });
  // Harmonic: no limit tau; a NaN deviation (a NaN position) still fails the check.
  summarize_elements("local_area", "triangle", std::span(scratch.deviations).first(triangle_count),
                     std::span(scratch.energies_pN_um).first(triangle_count), INFINITY, out);

  parallel_for(triangle_count, [&](std::size_t t) {
    const double coefficient_pN_per_um = -modulus_pN_per_um_ * scratch.deviations[t];
    set_area_gradient_slots(context, t, coefficient_pN_per_um, scratch.slot_forces_pN);
  });
  context.stencils.triangle.gather(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
