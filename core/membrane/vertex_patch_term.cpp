// The per-vertex form of the angle terms (vertex_patch.hpp): the shared evaluation and
// HemoCell 2.x's per-vertex bending. The area difference and total curvature in this form are in
// curvature_sum_term.cpp, beside their edge forms.
#include <span>

#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"
#include "membrane/vertex_patch.hpp"

namespace rbcsim::membrane {

void VertexPatchTerm::evaluate(const TermContext& context, TermScratch& scratch,
                               TermForces& out) const {
  const auto vertices = context.topology.vertex_count();
  measure_vertex_patches(context.positions_um, context.triangles, context.topology,
                         std::span(scratch.slot_forces_pN).first(vertices),
                         std::span(scratch.deviations).first(vertices));
  measure(context, scratch, out);
  // Each push once, into energies_pN_um (summed by measure, free now), then gathered.
  const auto pushes_pN = std::span(scratch.energies_pN_um).first(vertices);
  parallel_for(vertices, [&](std::size_t v) { pushes_pN[v] = push_pN(scratch, vertices, v); });
  gather_vertex_pushes(context.topology, std::span(scratch.slot_forces_pN).first(vertices),
                       pushes_pN, out.forces_pN);
}

VertexBendingTerm::VertexBendingTerm(const MembraneParameters& parameters,
                                     const ReferenceState& reference)
    : VertexPatchTerm(ForceLaw::with_linear_term(kTau), parameters.k_bend_kBT, parameters),
      mean_edge_um_(mean_reference_edge_um(reference)) {}

void VertexBendingTerm::measure(const TermContext& context, TermScratch& scratch,
                                TermForces& out) const {
  const auto vertices = context.topology.vertex_count();
  const auto offsets_um = std::span(scratch.deviations).first(vertices);
  const auto deviations = std::span(scratch.deviations).subspan(vertices, vertices);
  const auto energies = std::span(scratch.energies_pN_um).first(vertices);
  const double energy_scale_pN_um = force_scale_pN_ * mean_edge_um_;
  parallel_for(vertices, [&](std::size_t v) {
    deviations[v] = (offsets_um[v] - context.reference.vertex_offsets_um[v]) / mean_edge_um_;
    energies[v] = energy_scale_pN_um * law_.energy(deviations[v]);
  });
  summarize_elements("bend", "vertex", deviations, energies, law_.tau(), out);
}

double VertexBendingTerm::push_pN(const TermScratch& scratch, std::size_t vertex_count,
                                  std::size_t vertex) const {
  return -force_scale_pN_ * law_.slope(scratch.deviations[vertex_count + vertex]);
}

}  // namespace rbcsim::membrane
