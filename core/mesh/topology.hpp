// Connectivity of a closed, oriented 2-manifold triangle mesh, built once per cell.
//
// Every interior edge has two triangles. The edge is stored oriented so that `triangle0` runs
// vertex0 -> vertex1 in its counter-clockwise order and `triangle1` runs vertex1 -> vertex0;
// `wing0` / `wing1` are the vertices opposite the edge in triangle0 / triangle1 (the paper's
// Fig. 4: the edge v1-v3 and the two "wing" vertices). With outward normals n0, n1 the signed
// dihedral angle of the edge is positive where the surface is convex (see geometry.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

struct Edge {
  std::int32_t vertex0;
  std::int32_t vertex1;
  std::int32_t wing0;  // opposite vertex in triangle0
  std::int32_t wing1;  // opposite vertex in triangle1
  std::int32_t triangle0;
  std::int32_t triangle1;
};

class MeshTopology {
 public:
  // Throws std::invalid_argument naming the first defect if the mesh is not a closed, consistently
  // oriented 2-manifold (an edge with one triangle, more than two, or two triangles that traverse
  // it in the same direction). Mesh import runs the detailed checks first and reports them
  // properly.
  static MeshTopology build(const TriangleMesh& mesh);

  const std::vector<Edge>& edges() const { return edges_; }
  // Triangles around each vertex (compressed rows: triangles_of_vertex(v) spans
  // vertex_triangle_offsets[v] .. vertex_triangle_offsets[v + 1]).
  const std::vector<std::int32_t>& vertex_triangle_offsets() const {
    return vertex_triangle_offsets_;
  }
  const std::vector<std::int32_t>& vertex_triangles() const { return vertex_triangles_; }
  // Edges touching each vertex, compressed in the same way.
  const std::vector<std::int32_t>& vertex_edge_offsets() const { return vertex_edge_offsets_; }
  const std::vector<std::int32_t>& vertex_edges() const { return vertex_edges_; }

  std::size_t vertex_count() const { return vertex_triangle_offsets_.size() - 1; }
  std::size_t edge_count() const { return edges_.size(); }
  std::size_t triangle_count() const { return triangle_count_; }
  // V - E + F; 2 for a closed genus-0 surface.
  long euler_characteristic() const;

 private:
  std::vector<Edge> edges_;
  std::vector<std::int32_t> vertex_triangle_offsets_;
  std::vector<std::int32_t> vertex_triangles_;
  std::vector<std::int32_t> vertex_edge_offsets_;
  std::vector<std::int32_t> vertex_edges_;
  std::size_t triangle_count_ = 0;
};

}  // namespace rbcsim::mesh
