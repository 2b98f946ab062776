// The vectorised element passes. Each loop body is plain arithmetic on simd::Xyz (no Eigen, no
// library calls), its loop is `omp simd`, and this file is compiled with -fno-math-errno
// -fno-trapping-math (CMakeLists.txt) so that sqrt and the selects of the branch-free atan2 can
// be widened; neither flag changes a result. -ffp-contract=off keeps every operation rounded as
// written, so the baseline, AVX2 and AVX-512 clones compute the same bits. After each loop a
// scalar loop over the block forms its partial sums in element order.
#include "membrane/optimised_passes.hpp"

#include <algorithm>
#include <cmath>

#include "membrane/simd_math.hpp"
#include "membrane/surface_energies.hpp"

namespace rbcsim::membrane::optimised {
namespace {

using simd::Xyz;
using simd::XyzArrays;

// The elements of one block. 32-bit indices: with a 64-bit induction variable GCC 12 does not
// vectorise the loads of the vertex positions.
struct BlockRange {
  std::int32_t begin;
  std::int32_t end;
};
BlockRange block_range(std::size_t block, std::size_t elements) {
  const std::size_t begin = block * kBlockSize;
  return {static_cast<std::int32_t>(begin),
          static_cast<std::int32_t>(std::min(elements, begin + kBlockSize))};
}

XyzArrays arrays(Vec3Arrays& vectors) {
  return {vectors.x.data(), vectors.y.data(), vectors.z.data()};
}
// The same from entry `first` on.
XyzArrays shifted(Vec3Arrays& vectors, std::size_t first) {
  return {vectors.x.data() + first, vectors.y.data() + first, vectors.z.data() + first};
}

// The two distributions of the angle terms (hinge.hpp), as the edge pass computes their patterns.
enum class Pattern {
  // P = dtheta/dx (Bridson, Marino & Fedkiw 2003): dtheta/dwing_k = -N_k l / |N_k|^2, and the
  // ends follow from alpha_k = (wing_k - vertex0) . e / l^2; weights l and theta.
  gradient,
  // Wings -n_k, both ends (n0 + n1)/2 (Eqs. 15-18 with Eq. 18's sign), pushed with a = -F, F the
  // signed push of Eqs. 7, 10, 11; weights 1 and 0.
  paper,
};

// `gradient`: c = K slope / (2 |S0|) with K / |S0| = sqrt 3 k kBT / L0 (curvature_sum_term.cpp).
double gradient_cell_scale(double force_scale_pN) { return std::sqrt(3.0) / 2.0 * force_scale_pN; }
// `paper` pushes with the law's force itself.
double paper_bend_scale(double force_scale_pN, double) { return force_scale_pN; }
double paper_cell_scale(double force_scale_pN) { return force_scale_pN; }

// dtheta/dx by role into `out` where `on` is 1 (Bridson, Marino & Fedkiw 2003):
// dtheta/dwing_k = -N_k l / |N_k|^2, and the ends follow from alpha_k = (wing_k - vertex0) . e /
// l^2; axis = vertex1 - vertex0, N_k the triangles' normals of measure_edges.
[[gnu::always_inline]] inline void store_angle_gradients(const std::array<XyzArrays, 4>& out,
                                                         std::int32_t e, Xyz vertex0, Xyz wing0,
                                                         Xyz wing1, Xyz axis, Xyz normal0,
                                                         Xyz normal1, double length,
                                                         double inverse_length, double on) {
  const Xyz wing0_gradient = (-length / dot(normal0, normal0)) * normal0;
  const Xyz wing1_gradient = (-length / dot(normal1, normal1)) * normal1;
  const double inverse_length_squared = inverse_length * inverse_length;
  const double alpha0 = dot(wing0 - vertex0, axis) * inverse_length_squared;
  const double alpha1 = dot(wing1 - vertex0, axis) * inverse_length_squared;
  out[0].store_where(e, (alpha0 - 1.0) * wing0_gradient + (alpha1 - 1.0) * wing1_gradient, on);
  out[1].store_where(e, (-alpha0) * wing0_gradient - alpha1 * wing1_gradient, on);
  out[2].store_where(e, wing0_gradient, on);
  out[3].store_where(e, wing1_gradient, on);
}

// The loop body uses only Xyz values and plain doubles, no structs of them: a struct would stay
// in memory (OpenMP privatises it per lane) and keep the loop from vectorising.
template <Pattern kPattern>
[[gnu::always_inline]] inline void measure_edges(const FusedConstants& constants,
                                                 const HingeStencils& hinges, BlockRange range,
                                                 const double* positions_xyz,
                                                 OptimisedScratch& scratch) {
  const auto* vertices = hinges.vertices.data();
  const double* reference_lengths = hinges.reference_lengths_um.data();
  const double* inverse_reference_lengths = hinges.inverse_reference_lengths_per_um.data();
  const double* reference_angles = hinges.reference_angles_rad.data();
  const std::array<XyzArrays, 4> patterns = {
      arrays(scratch.hinge_patterns[0]), arrays(scratch.hinge_patterns[1]),
      arrays(scratch.hinge_patterns[2]), arrays(scratch.hinge_patterns[3])};
  const XyzArrays unit_axes = arrays(scratch.unit_axes);
  double* bend_coefficients = scratch.bend_coefficients.data();
  double* link_coefficients = scratch.link_coefficients_pN.data();
  double* angle_weights = scratch.angle_weights.data();
  double* length_weights = scratch.length_weights.data();
  double* angle_signs = scratch.angle_signs.data();
  double* link_deviations = scratch.link_deviations.data();
  double* bend_deviations = scratch.bend_deviations_rad.data();
  double* half_curvatures = scratch.half_curvatures_um.data();
  // Switches as 0/1 numbers: GCC vectorises a select on a compared double, not on a bool. Without
  // angle terms the patterns are zero, so a degenerate hinge cannot add a NaN elsewhere.
  const double link_on = constants.enabled[kLink] ? 1.0 : 0.0;
  const double bend_on = constants.enabled[kBend] ? 1.0 : 0.0;
  const double patterns_on = constants.angle_terms ? 1.0 : 0.0;
  const ScaledLaw link = constants.link;
  const ScaledLaw bend = constants.bend;
  const bool helfrich_on = constants.enabled[kHelfrich];
  double* lengths = scratch.lengths_um.data();
  double* angles = scratch.angles_rad.data();
  const std::array<XyzArrays, 4> angle_gradients = {
      arrays(scratch.angle_gradients_per_um[0]), arrays(scratch.angle_gradients_per_um[1]),
      arrays(scratch.angle_gradients_per_um[2]), arrays(scratch.angle_gradients_per_um[3])};

#pragma omp simd
  for (std::int32_t e = range.begin; e < range.end; ++e) {
    const Xyz vertex0 = simd::load(positions_xyz, vertices[e][0]);
    const Xyz vertex1 = simd::load(positions_xyz, vertices[e][1]);
    const Xyz wing0 = simd::load(positions_xyz, vertices[e][2]);
    const Xyz wing1 = simd::load(positions_xyz, vertices[e][3]);
    const Xyz axis = vertex1 - vertex0;
    const double length = std::sqrt(dot(axis, axis));
    const double inverse_length = 1.0 / length;
    // Outward normals of the two triangles, |N_k| = 2 A_k (hinge.hpp).
    const Xyz normal0 = cross(axis, wing0 - vertex0);
    const Xyz normal1 = cross(vertex0 - vertex1, wing1 - vertex1);
    // As mesh::signed_dihedral_angle_rad: atan2 of sin and cos, both scaled by |N0||N1|.
    const double angle_rad =
        simd::atan2(dot(cross(normal0, normal1), axis) * inverse_length, dot(normal0, normal1));

    if constexpr (kPattern == Pattern::gradient) {
      store_angle_gradients(patterns, e, vertex0, wing0, wing1, axis, normal0, normal1, length,
                            inverse_length, patterns_on);
      angle_weights[e] = length;
      length_weights[e] = angle_rad;
    } else {
      const Xyz unit_normal0 = (1.0 / std::sqrt(dot(normal0, normal0))) * normal0;
      const Xyz unit_normal1 = (1.0 / std::sqrt(dot(normal1, normal1))) * normal1;
      const Xyz ends = 0.5 * (unit_normal0 + unit_normal1);
      patterns[0].store_where(e, ends, patterns_on);
      patterns[1].store_where(e, ends, patterns_on);
      patterns[2].store_where(e, (-1.0) * unit_normal0, patterns_on);
      patterns[3].store_where(e, (-1.0) * unit_normal1, patterns_on);
      angle_weights[e] = 1.0;
      length_weights[e] = 0.0;
    }
    angle_signs[e] = simd::sign(angle_rad);
    unit_axes.store(e, inverse_length * axis);

    const double link_deviation = (length - reference_lengths[e]) * inverse_reference_lengths[e];
    const double bend_deviation_rad = angle_rad - reference_angles[e];
    link_deviations[e] = link_deviation;
    bend_deviations[e] = bend_deviation_rad;
    link_coefficients[e] = simd::where(link_on, link.coefficient(link_deviation));
    bend_coefficients[e] = simd::where(bend_on, bend.coefficient(bend_deviation_rad));
    half_curvatures[e] = 0.5 * length * angle_rad;
    if (helfrich_on) {  // loop-invariant: the compiler keeps two versions of the loop
      lengths[e] = length;
      angles[e] = angle_rad;
      store_angle_gradients(angle_gradients, e, vertex0, wing0, wing1, axis, normal0, normal1,
                            length, inverse_length, 1.0);
    }
  }

  EdgeBlockSums sums;
  for (std::int32_t e = range.begin; e < range.end; ++e) {
    sums.link_max_abs_deviation =
        simd::max_magnitude(sums.link_max_abs_deviation, link_deviations[e]);
    sums.bend_max_abs_deviation =
        simd::max_magnitude(sums.bend_max_abs_deviation, bend_deviations[e]);
    sums.signed_curvature_um += half_curvatures[e];
    sums.absolute_curvature_um += std::abs(half_curvatures[e]);
  }
  scratch.edge_blocks[static_cast<std::size_t>(range.begin) / kBlockSize] = sums;
}

template <Pattern kPattern>
RBCSIM_MEMBRANE_VECTOR_CLONES void measure_edge_block(const FusedConstants& constants,
                                                      const HingeStencils& hinges,
                                                      std::size_t block,
                                                      const double* positions_xyz,
                                                      OptimisedScratch& scratch) {
  measure_edges<kPattern>(constants, hinges, block_range(block, hinges.vertices.size()),
                          positions_xyz, scratch);
}

constexpr FusedDistribution kFusedDistributions[] = {
    {"paper", measure_edge_block<Pattern::paper>, paper_bend_scale, paper_cell_scale},
    {"gradient", measure_edge_block<Pattern::gradient>, gradient_bend_scale, gradient_cell_scale},
};

}  // namespace

std::span<const FusedDistribution> fused_distribution_table() { return kFusedDistributions; }

// Component pointers of four (three) vector arrays, for loops that read them by element.
template <std::size_t kCount>
struct ComponentPointers {
  std::array<const double*, kCount> x, y, z;
  explicit ComponentPointers(const std::array<Vec3Arrays, kCount>& vectors) {
    for (std::size_t i = 0; i < kCount; ++i) {
      x[i] = vectors[i].x.data();
      y[i] = vectors[i].y.data();
      z[i] = vectors[i].z.data();
    }
  }
  Xyz at(std::size_t i, std::int32_t element) const {
    return {x[i][element], y[i][element], z[i][element]};
  }
};

// F = -(a P_r + b g_r u) per role (OptimisedScratch), with g = (-1, +1, 0, 0); with helfrich
// also -(h l dtheta/dx_r) and b += h theta, h = kappa (u_0 + u_1) of the edge's ends
// (helfrich_term.cpp).
template <bool kWithHelfrich>
[[gnu::always_inline]] inline void weigh_edges(const SlotWeights& weights,
                                               const HingeStencils& hinges, BlockRange range,
                                               OptimisedScratch& scratch) {
  const std::size_t edges = scratch.angle_signs.size();
  const ComponentPointers<4> patterns(scratch.hinge_patterns);
  const ComponentPointers<4> angle_gradients(scratch.angle_gradients_per_um);
  const double* unit_x = scratch.unit_axes.x.data();
  const double* unit_y = scratch.unit_axes.y.data();
  const double* unit_z = scratch.unit_axes.z.data();
  const double* bend_coefficients = scratch.bend_coefficients.data();
  const double* link_coefficients = scratch.link_coefficients_pN.data();
  const double* angle_weights = scratch.angle_weights.data();
  const double* length_weights = scratch.length_weights.data();
  const double* angle_signs = scratch.angle_signs.data();
  const auto* vertices = hinges.vertices.data();
  const double* curvature_loads = scratch.helfrich_curvature_loads_pN.data();
  const double* lengths = scratch.lengths_um.data();
  const double* angles = scratch.angles_rad.data();
  const std::array<XyzArrays, 4> slots = {
      shifted(scratch.slot_forces_pN, 0), shifted(scratch.slot_forces_pN, edges),
      shifted(scratch.slot_forces_pN, 2 * edges), shifted(scratch.slot_forces_pN, 3 * edges)};
  const double w_link = weights[kLink];
  const double w_bend = weights[kBend];
  const double c_area_difference = weights[kAreaDifference];
  const double c_total_curvature = weights[kTotalCurvature];
  const double w_helfrich = weights[kHelfrich];

#pragma omp simd
  for (std::int32_t e = range.begin; e < range.end; ++e) {
    const double cell = c_area_difference + c_total_curvature * angle_signs[e];
    const double a = w_bend * bend_coefficients[e] + cell * angle_weights[e];
    double b = w_link * link_coefficients[e] + cell * length_weights[e];
    double helfrich_a = 0.0;
    if constexpr (kWithHelfrich) {
      const double h =
          w_helfrich * (curvature_loads[vertices[e][0]] + curvature_loads[vertices[e][1]]);
      helfrich_a = h * lengths[e];
      b += h * angles[e];
    }
    const Xyz along_axis = b * Xyz{unit_x[e], unit_y[e], unit_z[e]};
    const auto push = [&](std::size_t role) {
      const Xyz pushed = (-a) * patterns.at(role, e);
      if constexpr (kWithHelfrich) return pushed - helfrich_a * angle_gradients.at(role, e);
      return pushed;
    };
    slots[0].store(e, push(0) + along_axis);
    slots[1].store(e, push(1) - along_axis);
    slots[2].store(e, push(2));
    slots[3].store(e, push(3));
  }
}

RBCSIM_MEMBRANE_VECTOR_CLONES void weigh_edge_block(const SlotWeights& weights,
                                                    const HingeStencils& hinges, std::size_t block,
                                                    OptimisedScratch& scratch) {
  const BlockRange range = block_range(block, hinges.vertices.size());
  if (weights[kHelfrich] != 0.0) {
    weigh_edges<true>(weights, hinges, range, scratch);
  } else {
    weigh_edges<false>(weights, hinges, range, scratch);
  }
}

// F = w_area A_k + c_v N per corner k, plus g_t G_k with the area gradients G_k, where
// g_t = c_A (total_area) + c_L d_t (local_area, c_L = -K) - (lambda_a + lambda_b + lambda_c) / 3
// (helfrich, lambda = dE/dA_v at the corners).
template <bool kWithGradients, bool kWithHelfrich>
[[gnu::always_inline]] inline void weigh_triangles(const SlotWeights& weights,
                                                   const CornerStencils& stencils, BlockRange range,
                                                   OptimisedScratch& scratch) {
  const std::size_t triangles = scratch.area_deviations.size();
  const std::size_t first_slot = 4 * scratch.angle_signs.size();
  const double* normal_x = scratch.triangle_normals_um2.x.data();
  const double* normal_y = scratch.triangle_normals_um2.y.data();
  const double* normal_z = scratch.triangle_normals_um2.z.data();
  const ComponentPointers<3> area_forces(scratch.corner_area_forces_pN);
  const ComponentPointers<3> gradients(scratch.corner_area_gradients_um);
  const double* area_deviations = scratch.area_deviations.data();
  const auto* corners = stencils.corners.data();
  const double* area_loads = scratch.helfrich_area_loads_pN_per_um.data();
  const std::array<XyzArrays, 3> slots = {
      shifted(scratch.slot_forces_pN, first_slot),
      shifted(scratch.slot_forces_pN, first_slot + triangles),
      shifted(scratch.slot_forces_pN, first_slot + 2 * triangles)};
  const double w_area = weights[kArea];
  const double c_volume = weights[kVolume];
  const double c_total_area = weights[kTotalArea];
  const double c_local_area = weights[kLocalArea];
  const double w_helfrich = weights[kHelfrich];

#pragma omp simd
  for (std::int32_t t = range.begin; t < range.end; ++t) {
    const Xyz volume = c_volume * Xyz{normal_x[t], normal_y[t], normal_z[t]};
    double gradient_weight = 0.0;
    if constexpr (kWithGradients) {
      gradient_weight = c_total_area + c_local_area * area_deviations[t];
    }
    if constexpr (kWithHelfrich) {
      gradient_weight -=
          w_helfrich *
          (area_loads[corners[t][0]] + area_loads[corners[t][1]] + area_loads[corners[t][2]]) / 3.0;
    }
#pragma GCC unroll 3
    for (std::size_t corner = 0; corner < 3; ++corner) {
      Xyz force = w_area * area_forces.at(corner, t) + volume;
      if constexpr (kWithGradients) force = force + gradient_weight * gradients.at(corner, t);
      slots[corner].store(t, force);
    }
  }
}

RBCSIM_MEMBRANE_VECTOR_CLONES void weigh_triangle_block(const SlotWeights& weights,
                                                        const CornerStencils& corners,
                                                        std::size_t block,
                                                        OptimisedScratch& scratch) {
  const BlockRange range = block_range(block, corners.corners.size());
  // Without the area-gradient terms (or with them at zero weight) the gradient arrays may not
  // exist.
  if (weights[kHelfrich] != 0.0) {
    weigh_triangles<true, true>(weights, corners, range, scratch);
  } else if (weights[kTotalArea] != 0.0 || weights[kLocalArea] != 0.0) {
    weigh_triangles<true, false>(weights, corners, range, scratch);
  } else {
    weigh_triangles<false, false>(weights, corners, range, scratch);
  }
}

// With u = H - H0 and H = M / A (helfrich_term.cpp): kappa u, dE/dA_v = 2 kappa u (u - 2 H) and
// E_v = 2 kappa u^2 A_v. Scalar: a ring has five to seven entries.
void measure_vertex_block(const FusedConstants& constants, const mesh::MeshTopology& topology,
                          std::span<const double> reference_mean_curvatures_per_um,
                          std::size_t block, OptimisedScratch& scratch) {
  const BlockRange range = block_range(block, topology.vertex_count());
  const double kappa = constants.helfrich_modulus_pN_um;
  VertexBlockSums sums;
  for (std::int32_t v = range.begin; v < range.end; ++v) {
    const auto vertex = static_cast<std::size_t>(v);
    const double area_um2 = vertex_area_um2(topology, scratch.triangle_areas_um2, vertex);
    const double mean_curvature_per_um =
        integrated_mean_curvature_um(topology, scratch.lengths_um, scratch.angles_rad, vertex) /
        area_um2;
    const double departure = mean_curvature_per_um - reference_mean_curvatures_per_um[vertex];
    scratch.helfrich_departures_per_um[vertex] = departure;
    scratch.helfrich_curvature_loads_pN[vertex] = kappa * departure;
    scratch.helfrich_area_loads_pN_per_um[vertex] =
        2.0 * kappa * departure * (departure - 2.0 * mean_curvature_per_um);
    scratch.helfrich_energies_pN_um[vertex] = 2.0 * kappa * departure * departure * area_um2;
    sums.helfrich_max_abs_departure_per_um =
        simd::max_magnitude(sums.helfrich_max_abs_departure_per_um, departure);
  }
  scratch.vertex_blocks[block] = sums;
}

// K_b = (k_b kBT / L0) h, h = (sqrt 3 / 2) L0 (bending_term.cpp).
double gradient_bend_scale(double force_scale_pN, double length_scale_um) {
  return force_scale_pN * std::sqrt(3.0) / 2.0 * length_scale_um;
}

RBCSIM_MEMBRANE_VECTOR_CLONES void measure_triangle_block(const FusedConstants& constants,
                                                          const CornerStencils& stencils,
                                                          std::size_t block,
                                                          const double* positions_xyz,
                                                          OptimisedScratch& scratch) {
  const BlockRange range = block_range(block, stencils.corners.size());
  const auto* corners = stencils.corners.data();
  const double* reference_areas = stencils.reference_areas_um2.data();
  const double* inverse_reference_areas = stencils.inverse_reference_areas_per_um2.data();
  const double* area_forces_per_um = stencils.area_forces_per_um.data();
  const std::array<XyzArrays, 3> corner_forces = {arrays(scratch.corner_area_forces_pN[0]),
                                                  arrays(scratch.corner_area_forces_pN[1]),
                                                  arrays(scratch.corner_area_forces_pN[2])};
  const XyzArrays normals = arrays(scratch.triangle_normals_um2);
  double* area_deviations = scratch.area_deviations.data();
  double* volume_shares = scratch.volume_shares_um3.data();
  double* triangle_areas = scratch.triangle_areas_um2.data();
  const double area_on = constants.enabled[kArea] ? 1.0 : 0.0;  // see measure_edges
  const bool gradients_on = constants.area_gradients;
  std::array<XyzArrays, 3> gradients{};
  if (gradients_on) {
    for (std::size_t corner = 0; corner < 3; ++corner) {
      gradients[corner] = arrays(scratch.corner_area_gradients_um[corner]);
    }
  }
  const ScaledLaw area = constants.area;

#pragma omp simd
  for (std::int32_t t = range.begin; t < range.end; ++t) {
    const Xyz a = simd::load(positions_xyz, corners[t][0]);
    const Xyz b = simd::load(positions_xyz, corners[t][1]);
    const Xyz c = simd::load(positions_xyz, corners[t][2]);
    const Xyz normal = cross(b - a, c - a);
    normals.store(t, normal);
    const double normal_length = std::sqrt(dot(normal, normal));
    triangle_areas[t] = 0.5 * normal_length;
    const double deviation =
        (0.5 * normal_length - reference_areas[t]) * inverse_reference_areas[t];
    area_deviations[t] = deviation;
    // Divergence theorem: (area vector . centroid) / 3 = N . (a + b + c) / 18.
    volume_shares[t] = dot(normal, a + b + c) * (1.0 / 18.0);
    // Corner i: -(k_a kBT / L0) slope(d) (3 / P0) n x (x_{i+2} - x_{i+1}) (area_term.cpp).
    const double scale =
        simd::where(area_on, -area.coefficient(deviation) * area_forces_per_um[t] / normal_length);
    const Xyz scaled_normal = scale * normal;
    corner_forces[0].store(t, cross(scaled_normal, c - b));
    corner_forces[1].store(t, cross(scaled_normal, a - c));
    corner_forces[2].store(t, cross(scaled_normal, b - a));
    if (gradients_on) {  // loop-invariant: the compiler keeps two versions of the loop
      const Xyz half_unit_normal = (0.5 / normal_length) * normal;
      gradients[0].store(t, cross(half_unit_normal, c - b));
      gradients[1].store(t, cross(half_unit_normal, a - c));
      gradients[2].store(t, cross(half_unit_normal, b - a));
    }
  }

  TriangleBlockSums sums;
  for (std::int32_t t = range.begin; t < range.end; ++t) {
    sums.area_max_abs_deviation =
        simd::max_magnitude(sums.area_max_abs_deviation, area_deviations[t]);
    sums.volume_um3 += volume_shares[t];
    sums.area_um2 += triangle_areas[t];
  }
  scratch.triangle_blocks[block] = sums;
}

}  // namespace rbcsim::membrane::optimised
