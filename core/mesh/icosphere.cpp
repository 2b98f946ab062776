#include "mesh/icosphere.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace rbcsim::mesh {
namespace {

TriangleMesh unit_icosahedron() {
  const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh mesh;
  mesh.positions_um = {Vec3(-1, golden, 0),  Vec3(1, golden, 0),   Vec3(-1, -golden, 0),
                       Vec3(1, -golden, 0),  Vec3(0, -1, golden),  Vec3(0, 1, golden),
                       Vec3(0, -1, -golden), Vec3(0, 1, -golden),  Vec3(golden, 0, -1),
                       Vec3(golden, 0, 1),   Vec3(-golden, 0, -1), Vec3(-golden, 0, 1)};
  for (auto& position : mesh.positions_um) position.normalize();
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  return mesh;
}

}  // namespace

TriangleMesh subdivide_on_sphere(const TriangleMesh& coarse) {
  TriangleMesh fine;
  fine.positions_um = coarse.positions_um;
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> midpoint_of_edge;
  auto midpoint = [&](std::int32_t a, std::int32_t b) {
    const auto key = std::minmax(a, b);
    const auto [it, inserted] =
        midpoint_of_edge.try_emplace(key, static_cast<std::int32_t>(fine.positions_um.size()));
    if (inserted) {
      fine.positions_um.push_back((coarse.positions_um[a] + coarse.positions_um[b]).normalized());
    }
    return it->second;
  };
  fine.triangles.reserve(4 * coarse.triangle_count());
  for (const auto& [a, b, c] : coarse.triangles) {
    const auto ab = midpoint(a, b);
    const auto bc = midpoint(b, c);
    const auto ca = midpoint(c, a);
    fine.triangles.push_back({a, ab, ca});
    fine.triangles.push_back({b, bc, ab});
    fine.triangles.push_back({c, ca, bc});
    fine.triangles.push_back({ab, bc, ca});
  }
  return fine;
}

TriangleMesh unit_icosphere(int subdivisions) {
  if (subdivisions < 0 || subdivisions > 7) {
    throw std::invalid_argument("icosphere subdivisions must be in 0..7, got " +
                                std::to_string(subdivisions));
  }
  auto mesh = unit_icosahedron();
  for (int level = 0; level < subdivisions; ++level) mesh = subdivide_on_sphere(mesh);
  return mesh;
}

}  // namespace rbcsim::mesh
