// The optimised kernel ("optimised", the default): the six forces of force_terms.hpp, the
// whole-membrane area, Helfrich bending and the local area, fused.
// One evaluation is one OpenMP parallel region:
//  1. one vectorised pass over the edges measures each hinge ONCE (length, unit axis, both
//     triangle normals, dihedral angle theta) and writes its four pattern vectors and scalars:
//     all that bend, area_difference, total_curvature, link and helfrich need; one over the
//     triangles writes their normals, area forces, area gradients and volume shares
//     (optimised_passes.cpp); with helfrich, one over the vertices then gathers each ring's
//     l theta and areas into the vertex's Helfrich loads;
//  2. every thread reduces the cell sums (V, DeltaA, C) over fixed blocks of elements, in the same
//     order, checks every limit and turns the cell-level deviations into three coefficients;
//  3. one vectorised pass turns the patterns and coefficients into one force per slot (an
//     element's share of a vertex's force), and one gather per vertex sums its slots and caps.
// Every element writes only its own entries and every sum runs in an order fixed by the mesh
// (blocks of kBlockSize elements, a vertex's slots in slot order), so the result does not depend
// on the thread count. Per-term arrays and energies are computed only when asked for
// (ForceDetail::per_term), by step 3 again with all but one term weighted zero; the totals do
// not depend on that choice.
//
// Why the angle terms fuse. In the reference each angle term pushes an edge's four vertices with
// -(dE/dtheta_e dtheta_e/dx + dE/dl_e dl_e/dx) (`gradient`) or with F_e times the paper's pattern
// (`paper`, hinge.hpp), and the link with -(dE/dl_e) dl_e/dx. Per edge they add up to
//   F_slot = -(a_e P_slot + b_e dl_e/dx_slot),
// P = dtheta/dx (gradient) or ((n0 + n1)/2, (n0 + n1)/2, -n0, -n1) (paper, pushed with a = -F),
//   a_e = bend_e + (c_ad + c_tc sign theta_e) angle_weight_e,
//   b_e = link_e + (c_ad + c_tc sign theta_e) length_weight_e:
// with c = (K / 2|S0|) slope(d) the area difference has dE/dtheta_e = c l_e and dE/dl_e =
// c theta_e (curvature_sum_term.cpp) and the total curvature the same times sign(theta_e), since
// |theta| = sign(theta) theta (angle_weight = l, length_weight = theta); `paper` pushes every edge
// with c_ad and c_tc sign(theta_e) (angle_weight = 1, length_weight = 0). The volume force of a
// vertex is c_v times the sum of its triangles' normals (volume_term.cpp).
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/registry.hpp"
#include "membrane/force_terms.hpp"
#include "membrane/hinge.hpp"
#include "membrane/membrane_kernel.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/optimised_passes.hpp"
#include "membrane/simd_math.hpp"

namespace rbcsim::membrane {
namespace {

using namespace optimised;

// The fused term of that name, or none: a term registered beyond them (docs/architecture.md,
// "Adding a force term") runs beside the fused ones as its own ForceTerm until it is fused here.
std::optional<Term> fused_term_of(std::string_view name) {
  const auto* found = std::find(kTermNames.begin(), kTermNames.end(), name);
  if (found == kTermNames.end()) return std::nullopt;
  return static_cast<Term>(found - kTermNames.begin());
}

// Every distribution of hinge.cpp's table has its fused twin here (the constructor checks).
// The per-vertex form (a reproduction variant) has no fused twin: it runs on the reference kernel.
const FusedDistribution& find_fused_distribution(std::string_view name) {
  if (is_vertex_distribution(name)) {
    throw InputError("membrane.kernel",
                     "the optimised kernel fuses the hinge forms (paper, gradient) only; "
                     "membrane.distribution=vertex needs membrane.kernel=reference");
  }
  return find_entry(fused_distribution_table(), name, "membrane.distribution");
}

FusedConstants make_constants(const MembraneModel& model, const FusedDistribution& distribution) {
  const auto& p = model.parameters();
  const auto& reference = model.reference();
  const double length_um = p.force_length_scale_um;
  // k kBT / length of Eqs. 6-11 (LawTerm).
  const auto scale = [&](double k_kBT, double denominator_um) {
    return k_kBT * p.thermal_energy_pN_um / denominator_um;
  };
  const double link_pN = scale(p.k_link_kBT, p.persistence_length_um);
  const double bend_pN = scale(p.k_bend_kBT, length_um);
  const double area_pN = scale(p.k_area_kBT, length_um);
  const double volume_pN = scale(p.k_volume_kBT, length_um);
  const double area_difference_pN = scale(p.k_area_difference_kBT, length_um);
  const double total_curvature_pN = scale(p.k_total_curvature_kBT, length_um);
  const double volume_gradient_um2 = reference.mean_volume_gradient_um2;

  FusedConstants constants{
      .enabled = {},
      .angle_terms = false,
      // total_area, helfrich and local_area are harmonic: no limit, but NaN still fails.
      .tau = {p.tau_link, p.tau_bend_rad, p.tau_area, p.tau_volume, p.tau_area_difference,
              p.tau_total_curvature, std::numeric_limits<double>::infinity(),
              std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()},
      // Energy stiffnesses (the terms' files): link (k_l kBT / p) L0_e; bend K_b of the gradient
      // form in both distributions; area (k_a kBT / L0) 6 A0 / P0; volume (k_v kBT / L0) V0 / g0;
      // cell terms sqrt 3 |S0| k kBT / L0.
      .link = {ForceLaw::with_linear_term(p.tau_link), link_pN, link_pN},
      .bend = {ForceLaw::with_linear_term(p.tau_bend_rad),
               distribution.bend_scale(bend_pN, length_um),
               gradient_bend_scale(bend_pN, length_um)},
      .area = {ForceLaw::with_linear_term(p.tau_area), area_pN, area_pN * 6.0},
      // F_i = -(k_v kBT / L0) slope / (3 g0) times i's triangles' area vectors N / 2.
      .volume = {ForceLaw::divergent_only(p.tau_volume), volume_pN / (6.0 * volume_gradient_um2),
                 volume_pN * reference.volume_um3 / volume_gradient_um2},
      .area_difference = {ForceLaw::with_linear_term(p.tau_area_difference),
                          distribution.cell_scale(area_difference_pN),
                          std::sqrt(3.0) * area_difference_pN *
                              std::abs(reference.signed_curvature_sum_um)},
      .total_curvature = {ForceLaw::with_linear_term(p.tau_total_curvature),
                          distribution.cell_scale(total_curvature_pN),
                          std::sqrt(3.0) * total_curvature_pN *
                              reference.absolute_curvature_sum_um},
      .total_area_modulus_pN_per_um = p.total_area_modulus_uN_per_m,
      .local_area_modulus_pN_per_um = p.local_area_modulus_uN_per_m,
      .helfrich_modulus_pN_um = p.k_bend_kBT * p.thermal_energy_pN_um,
      .area_gradients = false,
  };
  for (auto name : model.kernel_term_names()) {
    if (const auto term = fused_term_of(name)) constants.enabled[*term] = true;
  }
  constants.angle_terms = constants.enabled[kBend] || constants.enabled[kAreaDifference] ||
                          constants.enabled[kTotalCurvature];
  constants.area_gradients = constants.enabled[kTotalArea] || constants.enabled[kLocalArea] ||
                             constants.enabled[kHelfrich];
  return constants;
}

HingeStencils make_hinge_stencils(const MembraneModel& model) {
  const auto& reference = model.reference();
  HingeStencils hinges;
  for (const auto& edge : model.topology().edges()) {
    hinges.vertices.push_back({edge.vertex0, edge.vertex1, edge.wing0, edge.wing1});
  }
  hinges.reference_lengths_um = reference.edge_lengths_um;
  for (double length_um : reference.edge_lengths_um) {
    hinges.inverse_reference_lengths_per_um.push_back(1.0 / length_um);
  }
  hinges.reference_angles_rad = reference.dihedral_angles_rad;
  return hinges;
}

CornerStencils make_corner_stencils(const MembraneModel& model) {
  const auto& reference = model.reference();
  CornerStencils corners;
  for (const auto& triangle : model.triangles()) {
    corners.corners.push_back({triangle[0], triangle[1], triangle[2], triangle[0]});
  }
  corners.reference_areas_um2 = reference.triangle_areas_um2;
  for (std::size_t t = 0; t < corners.corners.size(); ++t) {
    corners.inverse_reference_areas_per_um2.push_back(1.0 / reference.triangle_areas_um2[t]);
    corners.area_forces_per_um.push_back(3.0 / reference.triangle_perimeters_um[t]);
  }
  return corners;
}

// Slots of the gather, role-major so that each role's slots are contiguous per vertex:
// hinge slot r E + e (role r of edge e), then corner slot 4 E + k T + t (corner k of triangle t).
VertexGather make_incidence(const MembraneModel& model) {
  const auto& edges = model.topology().edges();
  const auto triangles = model.triangles();
  std::vector<std::int32_t> slot_vertices;
  const auto roles = {&mesh::Edge::vertex0, &mesh::Edge::vertex1, &mesh::Edge::wing0,
                      &mesh::Edge::wing1};
  for (auto role : roles) {
    for (const auto& edge : edges) slot_vertices.push_back(edge.*role);
  }
  for (std::size_t corner = 0; corner < 3; ++corner) {
    for (const auto& triangle : triangles) slot_vertices.push_back(triangle[corner]);
  }
  return VertexGather(slot_vertices, model.vertex_count());
}

// The result of step 2.
struct CellSummary {
  CellDeviations cell;
  std::array<double, kTermCount> max_abs_deviation{};  // per term, enabled or not
  // Index among the fused terms (registry order) of the first whose deviation reached its limit,
  // or -1.
  std::ptrdiff_t failed_term = -1;
  SlotWeights weights{};
};

class OptimisedKernel final : public MembraneKernel {
 public:
  explicit OptimisedKernel(const MembraneModel& model)
      : distribution_(&find_fused_distribution(model.parameters().distribution)),
        constants_(make_constants(model, *distribution_)),
        hinges_(make_hinge_stencils(model)),
        corners_(make_corner_stencils(model)),
        incidence_(make_incidence(model)) {
    // The term factories validate the parameters and the reference (e.g. DeltaA0 near zero):
    // this kernel accepts exactly what the reference kernel accepts.
    make_force_terms(model.kernel_term_names(), model.parameters(), model.reference());
    for (const auto& entry : hinge_distribution_table()) find_fused_distribution(entry.name);
    const auto names = model.kernel_term_names();
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (const auto term = fused_term_of(names[i])) {
        enabled_terms_.push_back(*term);
        fused_indices_.push_back(i);
      } else {
        unfused_.push_back({i, std::move(make_force_terms(std::span(names).subspan(i, 1),
                                                          model.parameters(), model.reference())
                                             .front())});
      }
    }
    if (!unfused_.empty()) {
      stencils_ =
          std::make_unique<MeshStencils>(MeshStencils::build(model.triangles(), model.topology()));
    }
  }

  MembraneWorkspace make_workspace(const MembraneModel& model) const override {
    MembraneWorkspace workspace;
    if (!unfused_.empty()) size_term_workspace(model, workspace);
    auto& s = workspace.optimised;
    const auto edges = edge_count();
    const auto triangles = triangle_count();
    for (auto& pattern : s.hinge_patterns) pattern.assign_zero(edges);
    s.unit_axes.assign_zero(edges);
    for (auto* per_edge :
         {&s.bend_coefficients, &s.link_coefficients_pN, &s.angle_weights, &s.length_weights,
          &s.angle_signs, &s.link_deviations, &s.bend_deviations_rad, &s.half_curvatures_um}) {
      per_edge->assign(edges, 0.0);
    }
    for (auto& corner : s.corner_area_forces_pN) corner.assign_zero(triangles);
    s.triangle_normals_um2.assign_zero(triangles);
    s.area_deviations.assign(triangles, 0.0);
    s.volume_shares_um3.assign(triangles, 0.0);
    s.triangle_areas_um2.assign(triangles, 0.0);
    if (constants_.area_gradients) {
      for (auto& corner : s.corner_area_gradients_um) corner.assign_zero(triangles);
    }
    if (constants_.enabled[kHelfrich]) {
      s.lengths_um.assign(edges, 0.0);
      s.angles_rad.assign(edges, 0.0);
      for (auto& role : s.angle_gradients_per_um) role.assign_zero(edges);
      const auto vertices = model.vertex_count();
      for (auto* per_vertex : {&s.helfrich_curvature_loads_pN, &s.helfrich_area_loads_pN_per_um,
                               &s.helfrich_energies_pN_um, &s.helfrich_departures_per_um}) {
        per_vertex->assign(vertices, 0.0);
      }
      s.vertex_blocks.assign(block_count(vertices), VertexBlockSums{});
    }
    s.slot_forces_pN.assign_zero(4 * edges + 3 * triangles);
    s.edge_blocks.assign(block_count(edges), EdgeBlockSums{});
    s.triangle_blocks.assign(block_count(triangles), TriangleBlockSums{});
    return workspace;
  }

  void compute(const MembraneModel& model, std::span<const Vec3> positions_um,
               MembraneWorkspace& workspace, MembraneForces& forces,
               ForceDetail detail) const override {
    auto& scratch = workspace.optimised;
    if (scratch.edge_blocks.size() != block_count(edge_count()) ||
        scratch.triangle_normals_um2.x.size() != triangle_count()) {
      throw std::invalid_argument("membrane forces: the workspace was not made by this model");
    }
    evaluate_unfused(model, positions_um, workspace, forces);
    // Vec3 is three contiguous doubles: the passes read the positions as x, y, z triples.
    const double* positions_xyz = positions_um.data()->data();
    const auto vertex_count = static_cast<std::ptrdiff_t>(model.vertex_count());
    const double cap_pN = model.parameters().vertex_force_cap_pN;
    CellSummary summary;  // thread 0's, for after the region
    std::size_t capped = 0;
    std::ptrdiff_t first_non_finite = vertex_count;
    // Three synchronisations (four with helfrich: after its vertex pass too): after step 1, after
    // step 3a, and the end of the region (which also completes the reductions of the `nowait`
    // gather).
#pragma omp parallel
    {
      measure_elements(positions_xyz, scratch);
      if (constants_.enabled[kHelfrich]) measure_vertices(model, scratch);
      // Every thread reduces the same block sums in the same order: the same summary on every
      // thread, with no thread waiting for another to publish it.
      const CellSummary own_summary = summarize(model, scratch);
      if (omp_get_thread_num() == 0) summary = own_summary;
      if (own_summary.failed_term < 0) {
        weigh_slots(own_summary.weights, scratch);
#pragma omp for schedule(static) nowait reduction(+ : capped) reduction(min : first_non_finite)
        for (std::ptrdiff_t v = 0; v < vertex_count; ++v) {
          Vec3 total_pN = sum_slots(static_cast<std::size_t>(v), scratch.slot_forces_pN);
          for (const auto& term : unfused_) {
            total_pN += forces.terms[term.index].forces_pN[static_cast<std::size_t>(v)];
          }
          bool finite = true;
          if (clamp_to_force_cap(total_pN, cap_pN, finite)) ++capped;
          if (!finite) first_non_finite = std::min(first_non_finite, v);
          forces.total_pN[static_cast<std::size_t>(v)] = total_pN;
        }
      }
    }
    forces.cell = summary.cell;
    for (std::size_t i = 0; i < enabled_terms_.size(); ++i) {
      forces.terms[fused_indices_[i]].max_abs_deviation =
          summary.max_abs_deviation[enabled_terms_[i]];
    }
    if (summary.failed_term >= 0) {
      report_limit(enabled_terms_[static_cast<std::size_t>(summary.failed_term)], scratch,
                   forces.cell);
    }
    require_finite_forces(static_cast<std::size_t>(first_non_finite), model.vertex_count());
    forces.capped_vertex_count = capped;
    if (detail == ForceDetail::per_term) {
      fill_term_detail(model, scratch, summary.weights, forces);
    } else {
      drop_term_detail(forces);
    }
  }

 private:
  std::size_t edge_count() const { return hinges_.vertices.size(); }

  // The unfused terms, each into its own entry of forces.terms (resized: no allocation after the
  // first call), on the reference kernel's geometry; the gather adds them before the cap.
  void evaluate_unfused(const MembraneModel& model, std::span<const Vec3> positions_um,
                        MembraneWorkspace& workspace, MembraneForces& forces) const {
    if (unfused_.empty()) return;
    measure_cell_geometry(positions_um, model.triangles(), model.topology(), workspace.geometry);
    const TermContext context{positions_um, model.triangles(), model.topology(),
                              *stencils_,   model.reference(), workspace.geometry};
    for (const auto& term : unfused_) {
      auto& out = forces.terms[term.index];
      out.forces_pN.resize(model.vertex_count());
      term.term->evaluate(context, workspace.scratch, out);
    }
  }
  std::size_t triangle_count() const { return corners_.corners.size(); }

  // Step 2: cell sums, deviations, limit checks, coefficients. Never throws (it runs inside the
  // parallel region); the caller reports a failed limit.
  CellSummary summarize(const MembraneModel& model, const OptimisedScratch& scratch) const {
    EdgeBlockSums edges;
    for (const auto& block : scratch.edge_blocks) {
      edges.link_max_abs_deviation =
          simd::max_magnitude(edges.link_max_abs_deviation, block.link_max_abs_deviation);
      edges.bend_max_abs_deviation =
          simd::max_magnitude(edges.bend_max_abs_deviation, block.bend_max_abs_deviation);
      edges.signed_curvature_um += block.signed_curvature_um;
      edges.absolute_curvature_um += block.absolute_curvature_um;
    }
    double helfrich_max_abs_departure_per_um = 0.0;
    for (const auto& block : scratch.vertex_blocks) {
      helfrich_max_abs_departure_per_um = simd::max_magnitude(
          helfrich_max_abs_departure_per_um, block.helfrich_max_abs_departure_per_um);
    }
    TriangleBlockSums triangles;
    for (const auto& block : scratch.triangle_blocks) {
      triangles.area_max_abs_deviation =
          simd::max_magnitude(triangles.area_max_abs_deviation, block.area_max_abs_deviation);
      triangles.volume_um3 += block.volume_um3;
      triangles.area_um2 += block.area_um2;
    }
    CellSummary summary;
    summary.cell = cell_deviations(model.reference(), triangles.volume_um3, triangles.area_um2,
                                   edges.signed_curvature_um, edges.absolute_curvature_um);
    const auto& cell = summary.cell;
    summary.max_abs_deviation = {
        edges.link_max_abs_deviation,     edges.bend_max_abs_deviation,
        triangles.area_max_abs_deviation, std::abs(cell.volume),
        std::abs(cell.area_difference),   std::abs(cell.total_curvature),
        std::abs(cell.total_area),        helfrich_max_abs_departure_per_um,
        triangles.area_max_abs_deviation};
    for (std::size_t i = 0; i < enabled_terms_.size(); ++i) {
      const Term term = enabled_terms_[i];
      // `!(|d| < tau)` also catches NaN.
      if (!(summary.max_abs_deviation[term] < constants_.tau[term])) {
        summary.failed_term = static_cast<std::ptrdiff_t>(i);
        return summary;
      }
    }
    const auto& enabled = constants_.enabled;
    summary.weights = {
        1.0,
        1.0,
        1.0,
        enabled[kVolume] ? -constants_.volume.coefficient(cell.volume) : 0.0,
        enabled[kAreaDifference] ? constants_.area_difference.coefficient(cell.area_difference)
                                 : 0.0,
        enabled[kTotalCurvature] ? constants_.total_curvature.coefficient(cell.total_curvature)
                                 : 0.0,
        enabled[kTotalArea] ? -constants_.total_area_modulus_pN_per_um * cell.total_area : 0.0,
        enabled[kHelfrich] ? 1.0 : 0.0,
        enabled[kLocalArea] ? -constants_.local_area_modulus_pN_per_um : 0.0};
    return summary;
  }

  // Step 1, inside the parallel region (orphaned worksharing loops; a barrier at the end).
  void measure_elements(const double* positions_xyz, OptimisedScratch& scratch) const {
    const auto edge_blocks = static_cast<std::ptrdiff_t>(scratch.edge_blocks.size());
    const auto triangle_blocks = static_cast<std::ptrdiff_t>(scratch.triangle_blocks.size());
#pragma omp for schedule(static) nowait
    for (std::ptrdiff_t b = 0; b < edge_blocks; ++b) {
      distribution_->measure_edge_block(constants_, hinges_, static_cast<std::size_t>(b),
                                        positions_xyz, scratch);
    }
#pragma omp for schedule(static)
    for (std::ptrdiff_t b = 0; b < triangle_blocks; ++b) {
      measure_triangle_block(constants_, corners_, static_cast<std::size_t>(b), positions_xyz,
                             scratch);
    }
  }

  // Step 1b, inside the parallel region likewise: helfrich's per-vertex loads.
  void measure_vertices(const MembraneModel& model, OptimisedScratch& scratch) const {
    const auto vertex_blocks = static_cast<std::ptrdiff_t>(scratch.vertex_blocks.size());
#pragma omp for schedule(static)
    for (std::ptrdiff_t b = 0; b < vertex_blocks; ++b) {
      measure_vertex_block(constants_, model.topology(),
                           model.reference().vertex_mean_curvatures_per_um,
                           static_cast<std::size_t>(b), scratch);
    }
  }

  // Step 3a, inside the parallel region likewise.
  void weigh_slots(const SlotWeights& weights, OptimisedScratch& scratch) const {
    const auto edge_blocks = static_cast<std::ptrdiff_t>(scratch.edge_blocks.size());
    const auto triangle_blocks = static_cast<std::ptrdiff_t>(scratch.triangle_blocks.size());
#pragma omp for schedule(static) nowait
    for (std::ptrdiff_t b = 0; b < edge_blocks; ++b) {
      weigh_edge_block(weights, hinges_, static_cast<std::size_t>(b), scratch);
    }
#pragma omp for schedule(static)
    for (std::ptrdiff_t b = 0; b < triangle_blocks; ++b) {
      weigh_triangle_block(weights, corners_, static_cast<std::size_t>(b), scratch);
    }
  }

  // Step 3b for one vertex: the sum of its slots. Two running sums (alternate slots, added at the
  // end) halve the chain of dependent additions; the order is still fixed by the mesh alone.
  Vec3 sum_slots(std::size_t vertex, const Vec3Arrays& slot_forces) const {
    const auto slots = incidence_.slots_of(vertex);
    Vec3 even = Vec3::Zero();
    Vec3 odd = Vec3::Zero();
    std::size_t k = 0;
    for (; k + 1 < slots.size(); k += 2) {
      even += slot_forces[static_cast<std::size_t>(slots[k])];
      odd += slot_forces[static_cast<std::size_t>(slots[k + 1])];
    }
    if (k < slots.size()) even += slot_forces[static_cast<std::size_t>(slots[k])];
    return even + odd;
  }

  // Per-term arrays (step 3 with one term's weight kept) and energies.
  void fill_term_detail(const MembraneModel& model, OptimisedScratch& scratch,
                        const SlotWeights& weights, MembraneForces& forces) const {
    prepare_term_arrays(forces, model.vertex_count());
    const auto vertex_count = static_cast<std::ptrdiff_t>(model.vertex_count());
#pragma omp parallel
    for (std::size_t i = 0; i < enabled_terms_.size(); ++i) {
      SlotWeights only_this_term{};
      only_this_term[enabled_terms_[i]] = weights[enabled_terms_[i]];
      weigh_slots(only_this_term, scratch);
      auto& out = forces.terms[fused_indices_[i]].forces_pN;
#pragma omp for schedule(static)
      for (std::ptrdiff_t v = 0; v < vertex_count; ++v) {
        const auto vertex = static_cast<std::size_t>(v);
        out[vertex] = sum_slots(vertex, scratch.slot_forces_pN);
      }
    }
    for (std::size_t i = 0; i < enabled_terms_.size(); ++i) {
      forces.terms[fused_indices_[i]].energy_pN_um =
          energy(enabled_terms_[i], model.reference(), scratch, forces.cell);
    }
  }

  // K energy(d) summed over the term's elements in element order, as the reference.
  double energy(Term term, const ReferenceState& reference, const OptimisedScratch& scratch,
                const CellDeviations& cell) const {
    double sum_pN_um = 0.0;
    switch (term) {
      case kLink:
        for (std::size_t e = 0; e < edge_count(); ++e) {
          sum_pN_um += constants_.link.energy_scale * reference.edge_lengths_um[e] *
                       constants_.link.law.energy(scratch.link_deviations[e]);
        }
        return sum_pN_um;
      case kBend:
        for (double deviation_rad : scratch.bend_deviations_rad) {
          sum_pN_um += constants_.bend.energy_scale * constants_.bend.law.energy(deviation_rad);
        }
        return sum_pN_um;
      case kArea:
        for (std::size_t t = 0; t < triangle_count(); ++t) {
          sum_pN_um += constants_.area.energy_scale * reference.triangle_areas_um2[t] /
                       reference.triangle_perimeters_um[t] *
                       constants_.area.law.energy(scratch.area_deviations[t]);
        }
        return sum_pN_um;
      case kVolume:
        return constants_.volume.energy_scale * constants_.volume.law.energy(cell.volume);
      case kAreaDifference:
        return constants_.area_difference.energy_scale *
               constants_.area_difference.law.energy(cell.area_difference);
      case kTotalCurvature:
        return constants_.total_curvature.energy_scale *
               constants_.total_curvature.law.energy(cell.total_curvature);
      case kTotalArea:
        return 0.5 * constants_.total_area_modulus_pN_per_um * reference.area_um2 *
               cell.total_area * cell.total_area;
      case kHelfrich:
        for (double vertex_energy_pN_um : scratch.helfrich_energies_pN_um) {
          sum_pN_um += vertex_energy_pN_um;
        }
        return sum_pN_um;
      case kLocalArea:
        for (std::size_t t = 0; t < triangle_count(); ++t) {
          const double deviation = scratch.area_deviations[t];
          sum_pN_um += 0.5 * constants_.local_area_modulus_pN_per_um *
                       reference.triangle_areas_um2[t] * deviation * deviation;
        }
        return sum_pN_um;
      case kTermCount:
        break;
    }
    throw std::logic_error("membrane energy of an unknown term");
  }

  // Throws the reference kernel's RuntimeFailure: the first element of `term` at its limit.
  void report_limit(Term term, const OptimisedScratch& scratch, const CellDeviations& cell) const {
    const double tau = constants_.tau[term];
    const auto first_beyond = [&](std::string_view kind, const std::vector<double>& deviations) {
      for (std::size_t i = 0; i < deviations.size(); ++i) {
        if (!(std::abs(deviations[i]) < tau)) {
          require_within_limit(kTermNames[term], std::string(kind) + " " + std::to_string(i),
                               deviations[i], tau);
        }
      }
    };
    const std::array<double, kTermCount> cell_deviation = {
        0.0, 0.0, 0.0, cell.volume, cell.area_difference, cell.total_curvature, cell.total_area,
        0.0, 0.0};
    switch (term) {
      case kLink:
        first_beyond("edge", scratch.link_deviations);
        break;
      case kBend:
        first_beyond("edge", scratch.bend_deviations_rad);
        break;
      case kArea:
      case kLocalArea:
        first_beyond("triangle", scratch.area_deviations);
        break;
      case kHelfrich:
        first_beyond("vertex", scratch.helfrich_departures_per_um);
        break;
      case kTotalArea:
        fail_non_finite_total_area(cell.total_area);
      default:
        require_within_limit(kTermNames[term], "the cell", cell_deviation[term], tau);
    }
    throw std::logic_error("membrane limit check: no element beyond the limit was found");
  }

  const FusedDistribution* distribution_;
  FusedConstants constants_;
  HingeStencils hinges_;
  CornerStencils corners_;
  VertexGather incidence_;
  std::vector<Term> enabled_terms_;         // the fused terms, in registry order
  std::vector<std::size_t> fused_indices_;  // their entries in MembraneForces::terms
  struct UnfusedTerm {
    std::size_t index;  // its entry in MembraneForces::terms
    std::unique_ptr<ForceTerm> term;
  };
  std::vector<UnfusedTerm> unfused_;
  std::unique_ptr<MeshStencils> stencils_;  // the unfused terms' (none without them)
};

}  // namespace

std::vector<std::string> fused_force_term_names() { return {kTermNames.begin(), kTermNames.end()}; }

std::unique_ptr<MembraneKernel> make_optimised_kernel(const MembraneModel& model) {
  return std::make_unique<OptimisedKernel>(model);
}

}  // namespace rbcsim::membrane
