#include "membrane/vertex_patch.hpp"

#include <cstdint>

#include "membrane/parallel.hpp"

namespace rbcsim::membrane {
namespace {

std::size_t index(std::int32_t i) { return static_cast<std::size_t>(i); }

// Calls visit(u) for every ring neighbour u of vertex v.
template <class Visit>
void for_each_neighbour(const mesh::MeshTopology& topology, std::size_t v, const Visit& visit) {
  const auto& offsets = topology.vertex_edge_offsets();
  for (auto k = index(offsets[v]); k < index(offsets[v + 1]); ++k) {
    const auto& edge = topology.edges()[index(topology.vertex_edges()[k])];
    visit(index(edge.vertex0) == v ? index(edge.vertex1) : index(edge.vertex0));
  }
}

// The ring size n_v of vertex v.
double ring_size(const mesh::MeshTopology& topology, std::size_t v) {
  const auto& offsets = topology.vertex_edge_offsets();
  return static_cast<double>(offsets[v + 1] - offsets[v]);
}

}  // namespace

void measure_vertex_patches(std::span<const Vec3> positions_um,
                            std::span<const mesh::Triangle> triangles,
                            const mesh::MeshTopology& topology, std::span<Vec3> normals,
                            std::span<double> offsets_um) {
  const auto& triangle_offsets = topology.vertex_triangle_offsets();
  parallel_for(topology.vertex_count(), [&](std::size_t v) {
    Vec3 normal = Vec3::Zero();
    for (auto k = index(triangle_offsets[v]); k < index(triangle_offsets[v + 1]); ++k) {
      const auto& c = triangles[index(topology.vertex_triangles()[k])];
      const Vec3 a = positions_um[index(c[0])];
      normal += (positions_um[index(c[1])] - a).cross(positions_um[index(c[2])] - a).normalized();
    }
    normal.normalize();
    Vec3 centroid = Vec3::Zero();
    for_each_neighbour(topology, v, [&](std::size_t u) { centroid += positions_um[u]; });
    centroid /= ring_size(topology, v);
    normals[v] = normal;
    offsets_um[v] = normal.dot(positions_um[v] - centroid);
  });
}

void gather_vertex_pushes(const mesh::MeshTopology& topology, std::span<const Vec3> normals,
                          std::span<const double> pushes_pN, std::span<Vec3> forces_pN) {
  parallel_for(topology.vertex_count(), [&](std::size_t v) {
    Vec3 force = pushes_pN[v] * normals[v];
    for_each_neighbour(topology, v, [&](std::size_t u) {
      force -= pushes_pN[u] / ring_size(topology, u) * normals[u];
    });
    forces_pN[v] = force;
  });
}

}  // namespace rbcsim::membrane
