#include <span>

#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

void HingeTerm::evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const {
  measure(context, scratch, out);
  const auto& edges = context.topology.edges();
  parallel_for(edges.size(), [&](std::size_t e) {
    distribute_(hinge_of(context.positions_um, edges[e]), edge_load(context, scratch, e),
                std::span(scratch.slot_forces_pN).subspan(4 * e).first<4>());
  });
  context.stencils.hinge.gather(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
