// Link force (Eq. 6). Per edge e, d = (L - L0_e)/L0_e and the energy E_e = K_e energy(d).
// Exact gradient: dE_e/dx_vertex1 = K_e slope(d) (1/L0_e) u, u the unit vector vertex0 -> vertex1,
// and the opposite on vertex0. Choosing K_e = (k_l kBT / p) L0_e makes the force on each end
// -(k_l kBT / p) slope(d) u: the magnitude of Eq. 6 exactly, at every length, directed along the
// edge (central, so it conserves momentum and angular momentum in both distributions).
#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

LinkTerm::LinkTerm(const MembraneParameters& parameters)
    : LawTerm(ForceLaw::with_linear_term(parameters.tau_link), parameters.k_link_kBT,
              parameters.persistence_length_um, parameters.thermal_energy_pN_um) {}

void LinkTerm::evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const {
  const auto& edges = context.topology.edges();
  const auto& lengths_um = context.geometry.edge_lengths_um;
  const auto& reference_lengths_um = context.reference.edge_lengths_um;
  parallel_for(edges.size(), [&](std::size_t e) {
    const double deviation = (lengths_um[e] - reference_lengths_um[e]) / reference_lengths_um[e];
    scratch.deviations[e] = deviation;
    scratch.energies_pN_um[e] = force_scale_pN_ * reference_lengths_um[e] * law_.energy(deviation);
  });
  summarize_elements("link", "edge", std::span(scratch.deviations).first(edges.size()),
                     std::span(scratch.energies_pN_um).first(edges.size()), law_.tau(), out);

  parallel_for(edges.size(), [&](std::size_t e) {
    const auto& edge = edges[e];
    const Vec3 unit_axis =
        (context.positions_um[edge.vertex1] - context.positions_um[edge.vertex0]) / lengths_um[e];
    const Vec3 force_on_vertex1_pN =
        -force_scale_pN_ * law_.slope(scratch.deviations[e]) * unit_axis;
    scratch.slot_forces_pN[2 * e] = -force_on_vertex1_pN;
    scratch.slot_forces_pN[2 * e + 1] = force_on_vertex1_pN;
  });
  context.stencils.edge.gather(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
