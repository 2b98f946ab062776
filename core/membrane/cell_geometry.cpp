#include "membrane/cell_geometry.hpp"

#include <cmath>

#include "membrane/parallel.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::membrane {

CellGeometry::CellGeometry(std::size_t triangle_count, std::size_t edge_count)
    : triangle_area_vectors_um2(triangle_count),
      edge_lengths_um(edge_count),
      dihedral_angles_rad(edge_count) {}

void measure_cell_geometry(std::span<const Vec3> positions_um,
                           std::span<const mesh::Triangle> triangles,
                           const mesh::MeshTopology& topology, CellGeometry& geometry) {
  const auto& edges = topology.edges();
  parallel_for(triangles.size(), [&](std::size_t t) {
    geometry.triangle_area_vectors_um2[t] = mesh::triangle_area_vector(positions_um, triangles[t]);
  });
  parallel_for(edges.size(), [&](std::size_t e) {
    geometry.edge_lengths_um[e] = mesh::edge_length_um(positions_um, edges[e]);
    geometry.dihedral_angles_rad[e] = mesh::signed_dihedral_angle_rad(positions_um, edges[e]);
  });

  // Divergence theorem per triangle: V = sum_t (area vector . centroid) / 3.
  double volume_um3 = 0.0;
  double area_um2 = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    area_um2 += geometry.triangle_area_vectors_um2[t].norm();
    const auto& corners = triangles[t];
    const Vec3 centroid =
        (positions_um[corners[0]] + positions_um[corners[1]] + positions_um[corners[2]]) / 3.0;
    volume_um3 += geometry.triangle_area_vectors_um2[t].dot(centroid) / 3.0;
  }
  geometry.volume_um3 = volume_um3;
  geometry.area_um2 = area_um2;

  double signed_sum_um = 0.0;
  double absolute_sum_um = 0.0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double curvature_um = 0.5 * geometry.edge_lengths_um[e] * geometry.dihedral_angles_rad[e];
    signed_sum_um += curvature_um;
    absolute_sum_um += std::abs(curvature_um);
  }
  geometry.signed_curvature_sum_um = signed_sum_um;
  geometry.absolute_curvature_sum_um = absolute_sum_um;
}

std::array<Vec3, 3> triangle_area_gradients_um(std::span<const Vec3> positions_um,
                                               const mesh::Triangle& triangle,
                                               const Vec3& area_vector_um2) {
  const Vec3 unit_normal = area_vector_um2.normalized();
  std::array<Vec3, 3> gradients;
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3& next = positions_um[triangle[(k + 1) % 3]];
    const Vec3& after = positions_um[triangle[(k + 2) % 3]];
    gradients[k] = 0.5 * unit_normal.cross(after - next);
  }
  return gradients;
}

}  // namespace rbcsim::membrane
