// Deterministic scatter-free force assembly. Each element (edge, triangle, hinge) writes the force
// on each of its vertices into its own "slot"; a VertexGather then sums, for every vertex, its
// slots in increasing slot order. The element loop and the vertex loop can both run in parallel
// and the result is bit-identical for any thread count (no atomics, no order-dependent sums).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::membrane {

class VertexGather {
 public:
  VertexGather() = default;
  // slot_vertices[s] is the vertex that slot s acts on.
  VertexGather(std::span<const std::int32_t> slot_vertices, std::size_t vertex_count);

  std::size_t slot_count() const { return slots_.size(); }
  // vertex_sums[v] = sum of slot_values over v's slots (overwrites; slot_values may be longer).
  void gather(std::span<const Vec3> slot_values, std::span<Vec3> vertex_sums) const;
  // vertex_sums[v] += the same sum (a term with two kinds of element, e.g. hinges and triangles).
  void add_gathered(std::span<const Vec3> slot_values, std::span<Vec3> vertex_sums) const;
  // The slots of `vertex` in increasing order, for kernels that compute slot values on the fly.
  std::span<const std::int32_t> slots_of(std::size_t vertex) const {
    return std::span(slots_).subspan(
        static_cast<std::size_t>(offsets_[vertex]),
        static_cast<std::size_t>(offsets_[vertex + 1] - offsets_[vertex]));
  }

 private:
  std::vector<std::int32_t> offsets_;  // compressed rows: slots of v are offsets_[v]..[v+1]
  std::vector<std::int32_t> slots_;
};

}  // namespace rbcsim::membrane
