// What MembraneModel::compute returns, and how much of it one call fills.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/force_term.hpp"
#include "membrane/reference_state.hpp"

namespace rbcsim::membrane {

// How much compute() fills. A time step needs only the totals; the per-term arrays and energies
// are for output steps. total_pN is bit-identical in both modes, so asking for the detail at an
// output step does not perturb a run.
enum class ForceDetail {
  // total_pN, cell, capped_vertex_count and every term's max_abs_deviation (the limit checks
  // always run). Every term's forces_pN is left empty and its energy_pN_um is NaN.
  totals,
  // Everything, including every term's forces_pN and energy_pN_um.
  per_term,
};

// Relative deviations of the cell-level measures from the reference (whether or not their terms
// are enabled): d_V = (V - V0)/V0, d_DeltaA = (DeltaA - DeltaA0)/|DeltaA0|, d_C = (C - C0)/C0.
// d_DeltaA is not finite when DeltaA0 = 0.
struct CellDeviations {
  double volume = 0.0;
  double total_area = 0.0;
  double area_difference = 0.0;
  double total_curvature = 0.0;
};

// The deviations of a shape with these cell measures (the sums are those of ReferenceState).
CellDeviations cell_deviations(const ReferenceState& reference, double volume_um3, double area_um2,
                               double signed_curvature_sum_um, double absolute_curvature_sum_um);

struct MembraneForces {
  // Sum of the enabled terms per vertex, each vertex clamped to vertex_force_cap_pN, pN.
  std::vector<Vec3> total_pN;
  // One entry per enabled term, in registry order (force_terms.hpp), unclamped.
  std::vector<TermForces> terms;
  CellDeviations cell;
  // Vertices whose total force exceeded the cap in this evaluation (and were clamped).
  std::size_t capped_vertex_count = 0;

  // NaN after a ForceDetail::totals evaluation (the energies were not computed).
  double total_energy_pN_um() const;
  // Throws std::out_of_range for a term that is not enabled.
  const TermForces& term(std::string_view name) const;
};

// For kernels: size every term's forces_pN for `vertex_count` vertices before a per-term
// evaluation (no allocation when they had that size before), and empty them and set the energies
// to NaN after a totals-only one (so that no stale per-term number survives).
void prepare_term_arrays(MembraneForces& forces, std::size_t vertex_count);
void drop_term_detail(MembraneForces& forces);

}  // namespace rbcsim::membrane
