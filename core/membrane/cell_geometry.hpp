// Measures of one cell's current shape that several force terms share, computed once per force
// evaluation into caller-owned arrays (no allocation per call).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

struct CellGeometry {
  // (1/2)(b - a) x (c - a) per triangle: outward normal times area, um^2.
  std::vector<Vec3> triangle_area_vectors_um2;
  std::vector<double> edge_lengths_um;
  // Signed angle between the outward normals of the edge's triangles (convex positive), rad.
  std::vector<double> dihedral_angles_rad;
  double volume_um3 = 0.0;
  double area_um2 = 0.0;  // the whole membrane's, sum of the triangles' areas
  // sum_j l_j theta_j / 2 = DeltaA / (2 D0) (Eqs. 12-13) and sum_j l_j |theta_j| / 2 = C / (2 D0)
  // (Eq. 14), um. D0 cancels in every relative deviation, so it is never needed.
  double signed_curvature_sum_um = 0.0;
  double absolute_curvature_sum_um = 0.0;

  CellGeometry() = default;
  CellGeometry(std::size_t triangle_count, std::size_t edge_count);
};

// Fills `geometry` (sized for this mesh): the per-element measures in parallel, the cell sums
// serially in element order so that they do not depend on the thread count.
// The gradient of a triangle's area by its corners, dA/dx_k = (1/2) n x (x_{k+2} - x_{k+1}) for a
// counter-clockwise triangle with area vector `area_vector_um2` (in-plane, perpendicular to the
// opposite edge), um. Shared by every area-based term.
std::array<Vec3, 3> triangle_area_gradients_um(std::span<const Vec3> positions_um,
                                               const mesh::Triangle& triangle,
                                               const Vec3& area_vector_um2);

void measure_cell_geometry(std::span<const Vec3> positions_um,
                           std::span<const mesh::Triangle> triangles,
                           const mesh::MeshTopology& topology, CellGeometry& geometry);

}  // namespace rbcsim::membrane
