#include "mesh/topology.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rbcsim::mesh {
namespace {

struct HalfEdge {
  std::int32_t from;
  std::int32_t to;
  std::int32_t triangle;
  std::int32_t opposite_vertex;
  // Undirected key: edges are grouped by their sorted vertex pair.
  std::pair<std::int32_t, std::int32_t> key() const {
    return {std::min(from, to), std::max(from, to)};
  }
};

std::string describe(const HalfEdge& half_edge) {
  return "edge (" + std::to_string(half_edge.key().first) + ", " +
         std::to_string(half_edge.key().second) + ")";
}

std::vector<HalfEdge> sorted_half_edges(const TriangleMesh& mesh) {
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * mesh.triangle_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& corners = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      half_edges.push_back(
          {corners[k], corners[(k + 1) % 3], static_cast<std::int32_t>(t), corners[(k + 2) % 3]});
    }
  }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return std::pair(a.key(), a.triangle) < std::pair(b.key(), b.triangle);
  });
  return half_edges;
}

Edge pair_into_edge(const HalfEdge& first, const HalfEdge& second) {
  if (first.from != second.to || first.to != second.from) {
    throw std::invalid_argument(describe(first) +
                                " is traversed in the same direction by two triangles "
                                "(inconsistent orientation)");
  }
  return {first.from,     first.to,       first.opposite_vertex, second.opposite_vertex,
          first.triangle, second.triangle};
}

// Compressed-row adjacency from (row, value) pairs, rows 0..row_count-1.
void compress(std::size_t row_count,
              const std::vector<std::pair<std::int32_t, std::int32_t>>& pairs,
              std::vector<std::int32_t>& offsets, std::vector<std::int32_t>& values) {
  offsets.assign(row_count + 1, 0);
  for (const auto& [row, value] : pairs) ++offsets[row + 1];
  for (std::size_t r = 0; r < row_count; ++r) offsets[r + 1] += offsets[r];
  values.assign(pairs.size(), 0);
  auto cursor = offsets;
  for (const auto& [row, value] : pairs) values[cursor[row]++] = value;
}

}  // namespace

MeshTopology MeshTopology::build(const TriangleMesh& mesh) {
  const auto vertex_count = mesh.vertex_count();
  for (const auto& corners : mesh.triangles) {
    for (auto v : corners) {
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_count) {
        throw std::invalid_argument("triangle refers to vertex " + std::to_string(v) +
                                    " of a mesh with " + std::to_string(vertex_count) +
                                    " vertices");
      }
    }
  }
  MeshTopology topology;
  topology.triangle_count_ = mesh.triangle_count();
  const auto half_edges = sorted_half_edges(mesh);
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t group_end = i + 1;
    while (group_end < half_edges.size() && half_edges[group_end].key() == half_edges[i].key()) {
      ++group_end;
    }
    if (group_end - i == 1) {
      throw std::invalid_argument(describe(half_edges[i]) +
                                  " has only one triangle (open surface)");
    }
    if (group_end - i > 2) {
      throw std::invalid_argument(describe(half_edges[i]) + " is shared by " +
                                  std::to_string(group_end - i) + " triangles (non-manifold)");
    }
    topology.edges_.push_back(pair_into_edge(half_edges[i], half_edges[i + 1]));
    i = group_end;
  }

  std::vector<std::pair<std::int32_t, std::int32_t>> vertex_triangle_pairs;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (auto v : mesh.triangles[t])
      vertex_triangle_pairs.emplace_back(v, static_cast<std::int32_t>(t));
  }
  compress(vertex_count, vertex_triangle_pairs, topology.vertex_triangle_offsets_,
           topology.vertex_triangles_);

  std::vector<std::pair<std::int32_t, std::int32_t>> vertex_edge_pairs;
  for (std::size_t e = 0; e < topology.edges_.size(); ++e) {
    vertex_edge_pairs.emplace_back(topology.edges_[e].vertex0, static_cast<std::int32_t>(e));
    vertex_edge_pairs.emplace_back(topology.edges_[e].vertex1, static_cast<std::int32_t>(e));
  }
  compress(vertex_count, vertex_edge_pairs, topology.vertex_edge_offsets_, topology.vertex_edges_);
  return topology;
}

long MeshTopology::euler_characteristic() const {
  return static_cast<long>(vertex_count()) - static_cast<long>(edge_count()) +
         static_cast<long>(triangle_count());
}

}  // namespace rbcsim::mesh
