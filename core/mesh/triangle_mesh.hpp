// A closed triangulated surface: the membrane of one cell.
// Convention used everywhere: positions in micrometres; each triangle lists its vertices
// counter-clockwise seen from outside, so (b - a) x (c - a) points outward.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::mesh {

using Triangle = std::array<std::int32_t, 3>;

struct TriangleMesh {
  std::vector<Vec3> positions_um;
  std::vector<Triangle> triangles;

  std::size_t vertex_count() const { return positions_um.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
};

}  // namespace rbcsim::mesh
