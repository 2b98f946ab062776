// Local area force (Eq. 8). Per triangle t, d = (A - A0)/A0 and E_t = K_t energy(d).
// Exact gradient: dA/dx_i = (1/2) n x (x_{i+2} - x_{i+1}) for corner i of the counter-clockwise
// triangle (in-plane, perpendicular to the opposite edge, |dA/dx_i| = |opposite edge| / 2), so
//   F_i = -(K_t / A0) slope(d) (1/2) n x (x_{i+2} - x_{i+1}).
// Scale: we want the mean force magnitude over the three corners at the reference geometry to be
// Eq. 8's (k_a kBT / L0) slope(d). There the mean |dA/dx_i| is P0/6 (P0 = perimeter), hence
//   K_t = (k_a kBT / L0) * 6 A0 / P0
// and F_i = -(k_a kBT / L0) slope(d) (3 / P0) n x (x_{i+2} - x_{i+1}).
// (For an equilateral triangle every corner gets exactly Eq. 8's magnitude.) Central in both
// distributions: a gradient of a rigid-motion-invariant energy conserves both momenta.
#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

AreaTerm::AreaTerm(const MembraneParameters& parameters)
    : LawTerm(ForceLaw::with_linear_term(parameters.tau_area), parameters.k_area_kBT,
              parameters.force_length_scale_um, parameters.thermal_energy_pN_um) {}

void AreaTerm::evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const {
  const auto triangle_count = context.triangles.size();
  const auto& area_vectors_um2 = context.geometry.triangle_area_vectors_um2;
  const auto& reference_areas_um2 = context.reference.triangle_areas_um2;
  const auto& perimeters_um = context.reference.triangle_perimeters_um;
  parallel_for(triangle_count, [&](std::size_t t) {
    const double deviation =
        (area_vectors_um2[t].norm() - reference_areas_um2[t]) / reference_areas_um2[t];
    scratch.deviations[t] = deviation;
    const double stiffness_pN_um =
        force_scale_pN_ * 6.0 * reference_areas_um2[t] / perimeters_um[t];
    scratch.energies_pN_um[t] = stiffness_pN_um * law_.energy(deviation);
  });
  summarize_elements("area", "triangle", std::span(scratch.deviations).first(triangle_count),
                     std::span(scratch.energies_pN_um).first(triangle_count), law_.tau(), out);

  parallel_for(triangle_count, [&](std::size_t t) {
    // (3 / P0) n x (opposite edge) = (6 / P0) dA/dx_k.
    const double coefficient_pN_per_um =
        -force_scale_pN_ * law_.slope(scratch.deviations[t]) * 6.0 / perimeters_um[t];
    set_area_gradient_slots(context, t, coefficient_pN_per_um, scratch.slot_forces_pN);
  });
  context.stencils.triangle.gather(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
