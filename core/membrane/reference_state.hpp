// The stress-free reference of one cell (docs/physics.md): every L0, theta0, A0 and the cell's V0,
// DeltaA0, C0, captured from the initial mesh (the generated or imported shape is stress-free).
// A plain struct, so a restart can restore it and a test can edit it.
#pragma once

#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

struct ReferenceState {
  std::vector<double> edge_lengths_um;      // L0 per edge (Eq. 6)
  std::vector<double> dihedral_angles_rad;  // theta0 per edge (Eq. 7)
  std::vector<double> triangle_areas_um2;   // A0 per triangle (Eq. 8)
  // Perimeter per triangle: normalises the area force to the paper's magnitude (area_term.cpp).
  std::vector<double> triangle_perimeters_um;
  double volume_um3 = 0.0;  // V0 (Eq. 9)
  double area_um2 = 0.0;    // A0 of the whole membrane (the total_area term)
  // Mean over vertices of |dV/dx_i| = |(1/3) sum of the area vectors of i's triangles|, um^2:
  // normalises the volume force to the paper's magnitude (volume_term.cpp).
  double mean_volume_gradient_um2 = 0.0;
  // sum_j M0_j = DeltaA0 / (2 D0) and sum_j |M0_j| = C0 / (2 D0), with M_j = l_j theta_j / 2
  // (Eqs. 12-14), um. The monolayer thickness D0 cancels in the relative deviations.
  double signed_curvature_sum_um = 0.0;
  double absolute_curvature_sum_um = 0.0;
  // M0_i per vertex: the offset of each vertex from its ring's centroid along its patch normal
  // (vertex_patch.hpp), the reference of the per-vertex bending form, um.
  std::vector<double> vertex_offsets_um;
  // H0_v = M0_v / A0_v per vertex, Juelicher's mean curvature of the reference (the helfrich
  // term's spontaneous curvature, helfrich_term.cpp), 1/um.
  std::vector<double> vertex_mean_curvatures_per_um;
};

// The mean of the reference edge lengths L0, um.
double mean_reference_edge_um(const ReferenceState& reference);

// The reference of the same mesh scaled by `scale` (> 0) about any point: lengths times scale,
// areas times scale^2, the volume times scale^3, angles unchanged, curvatures divided by scale;
// what capture_reference_state gives for the scaled positions, to round-off. A cell growing to its
// size in the flow (CoupledSimulation::grow_cells) holds these on its way. Throws
// std::invalid_argument for a scale that is not positive.
ReferenceState scaled_reference(const ReferenceState& reference, double scale);

// Throws InputError (source "stress-free mesh") for a degenerate triangle or a non-positive
// enclosed volume (inward-facing triangles).
ReferenceState capture_reference_state(std::span<const Vec3> positions_um,
                                       std::span<const mesh::Triangle> triangles,
                                       const mesh::MeshTopology& topology);

}  // namespace rbcsim::membrane
