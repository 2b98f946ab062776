#include "membrane/vertex_gather.hpp"

#include "membrane/parallel.hpp"

namespace rbcsim::membrane {

VertexGather::VertexGather(std::span<const std::int32_t> slot_vertices, std::size_t vertex_count)
    : offsets_(vertex_count + 1, 0), slots_(slot_vertices.size()) {
  for (auto vertex : slot_vertices) ++offsets_[static_cast<std::size_t>(vertex) + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) offsets_[v + 1] += offsets_[v];
  auto cursor = offsets_;
  // Filling in slot order keeps every row sorted by slot.
  for (std::size_t s = 0; s < slot_vertices.size(); ++s) {
    slots_[cursor[slot_vertices[s]]++] = static_cast<std::int32_t>(s);
  }
}

void VertexGather::gather(std::span<const Vec3> slot_values, std::span<Vec3> vertex_sums) const {
  parallel_for(offsets_.size() - 1, [&](std::size_t v) {
    Vec3 sum = Vec3::Zero();
    for (auto k = offsets_[v]; k < offsets_[v + 1]; ++k) sum += slot_values[slots_[k]];
    vertex_sums[v] = sum;
  });
}

void VertexGather::add_gathered(std::span<const Vec3> slot_values,
                                std::span<Vec3> vertex_sums) const {
  parallel_for(offsets_.size() - 1, [&](std::size_t v) {
    Vec3 sum = Vec3::Zero();
    for (auto k = offsets_[v]; k < offsets_[v + 1]; ++k) sum += slot_values[slots_[k]];
    vertex_sums[v] += sum;
  });
}

}  // namespace rbcsim::membrane
