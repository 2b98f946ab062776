// Work arrays of the optimised membrane kernel (optimised_kernel.cpp explains each), allocated
// once per mesh by MembraneModel::make_workspace and overwritten by every evaluation. Structure of
// arrays: one contiguous array per component, so that the element passes load and store whole
// vector registers of consecutive elements.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::membrane {

// `count` three-component vectors, one array per component.
struct Vec3Arrays {
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> z;

  void assign_zero(std::size_t count) {
    x.assign(count, 0.0);
    y.assign(count, 0.0);
    z.assign(count, 0.0);
  }
  Vec3 operator[](std::size_t i) const { return {x[i], y[i], z[i]}; }
};

// Partial results of one fixed block of elements, reduced serially in block order so that the
// cell sums do not depend on the thread count. The maxima propagate NaN (a failed limit check).
struct EdgeBlockSums {
  double link_max_abs_deviation = 0.0;
  double bend_max_abs_deviation = 0.0;
  double signed_curvature_um = 0.0;    // sum of l theta / 2
  double absolute_curvature_um = 0.0;  // sum of l |theta| / 2
};
struct VertexBlockSums {
  double helfrich_max_abs_departure_per_um = 0.0;  // max |H_v - H0_v|
};
struct TriangleBlockSums {
  double area_max_abs_deviation = 0.0;
  double volume_um3 = 0.0;
  double area_um2 = 0.0;
};

struct OptimisedScratch {
  // Per edge. The force on the edge's slot of role r (vertex0, vertex1, wing0, wing1) is
  //   -(a P_r + b g_r unit_axis),  g = (-1, +1, 0, 0),
  //   a = bend_coefficient + m angle_weight,  b = link_coefficient + m length_weight,
  //   m = c_area_difference + c_total_curvature angle_sign.
  std::array<Vec3Arrays, 4> hinge_patterns;  // P_r by role
  Vec3Arrays unit_axes;                      // (vertex1 - vertex0) / l
  std::vector<double> bend_coefficients;     // dE/dtheta (gradient, pN um) or -F (paper, pN)
  std::vector<double> link_coefficients_pN;  // dE/dl of the link
  std::vector<double> angle_weights;         // l (gradient) or 1 (paper)
  std::vector<double> length_weights;        // theta (gradient) or 0 (paper)
  std::vector<double> angle_signs;           // sign(theta): -1, 0 or +1
  std::vector<double> link_deviations;
  std::vector<double> bend_deviations_rad;
  std::vector<double> half_curvatures_um;  // l theta / 2
  // Only with helfrich: l, theta and dtheta/dx by role (the exact gradient, whatever the
  // distribution of the other angle terms).
  std::vector<double> lengths_um;
  std::vector<double> angles_rad;
  std::array<Vec3Arrays, 4> angle_gradients_per_um;
  // Per vertex, only with helfrich: kappa (H_v - H0_v) (half of dE/dM_v), dE/dA_v and the energy.
  std::vector<double> helfrich_curvature_loads_pN;
  std::vector<double> helfrich_area_loads_pN_per_um;
  std::vector<double> helfrich_energies_pN_um;
  std::vector<double> helfrich_departures_per_um;
  // Per triangle: the area force on each corner, (b - a) x (c - a) (twice the area vector; the
  // volume force of a vertex is c_v times the sum over its triangles), and the volume shares.
  std::array<Vec3Arrays, 3> corner_area_forces_pN;
  Vec3Arrays triangle_normals_um2;
  std::vector<double> area_deviations;
  std::vector<double> volume_shares_um3;
  std::vector<double> triangle_areas_um2;
  // Per triangle, only with total_area, local_area or helfrich: dA/dx of each corner,
  // (1/2) n x (opposite edge).
  std::array<Vec3Arrays, 3> corner_area_gradients_um;
  // The force of every slot for the current weights: hinge slot r E + e (role r of edge e), then
  // corner slot 4 E + k T + t (corner k of triangle t). A vertex's force is the sum of its slots.
  Vec3Arrays slot_forces_pN;

  std::vector<EdgeBlockSums> edge_blocks;
  std::vector<TriangleBlockSums> triangle_blocks;
  std::vector<VertexBlockSums> vertex_blocks;  // only with helfrich
};

}  // namespace rbcsim::membrane
