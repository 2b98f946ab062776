// Whole-membrane area term (force_terms.hpp). d = (A - A0)/A0 with A = sum_t |A_t|, and
// E = K A0 d^2 / 2 = K (A - A0)^2 / (2 A0), the area-dilation energy of a membrane of area modulus
// K under uniform strain. Exact gradient: dA/dx_i = sum over i's triangles of
// (1/2) n_t x (x_{i+2} - x_{i+1}) (area_term.cpp), so F_i = -K d dA/dx_i, pN with K in pN/um.
// Central in both distributions: a gradient of a rigid-motion-invariant energy.
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

void fail_non_finite_total_area(double deviation) {
  throw RuntimeFailure("membrane term 'total_area': the cell's area is not finite (d = " +
                       std::to_string(deviation) + ")");
}

TotalAreaTerm::TotalAreaTerm(const MembraneParameters& parameters, const ReferenceState& reference)
    : modulus_pN_per_um_(parameters.total_area_modulus_uN_per_m),
      reference_area_um2_(reference.area_um2) {}

void TotalAreaTerm::evaluate(const TermContext& context, TermScratch& scratch,
                             TermForces& out) const {
  const double deviation = (context.geometry.area_um2 - reference_area_um2_) / reference_area_um2_;
  // Harmonic: no singular limit, but a non-finite area (a NaN position) is an instability.
  if (!std::isfinite(deviation)) fail_non_finite_total_area(deviation);
  out.energy_pN_um = 0.5 * modulus_pN_per_um_ * reference_area_um2_ * deviation * deviation;
  out.max_abs_deviation = std::abs(deviation);

  const double coefficient_pN_per_um = -modulus_pN_per_um_ * deviation;
  parallel_for(context.triangles.size(), [&](std::size_t t) {
    set_area_gradient_slots(context, t, coefficient_pN_per_um, scratch.slot_forces_pN);
  });
  context.stencils.triangle.gather(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
