// Closed test surfaces with exactly known insides, outward oriented.
#pragma once

#include <cmath>
#include <numbers>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::geometry::test_meshes {

// The box [low, high] as 12 triangles; every face is split along one diagonal.
inline mesh::TriangleMesh box_mesh(const Vec3& low, const Vec3& high) {
  mesh::TriangleMesh box;
  // Vertex v has coordinate bits (x, y, z) = (v & 1, v & 2, v & 4).
  for (int v = 0; v < 8; ++v) {
    box.positions_um.emplace_back(v & 1 ? high.x() : low.x(), v & 2 ? high.y() : low.y(),
                                  v & 4 ? high.z() : low.z());
  }
  box.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},   // z = low, z = high
                   {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},   // y = low, y = high
                   {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};  // x = low, x = high
  return box;
}

// A circular tube along x from 0 to length with flat end caps: `sides` vertices per ring on the
// circle of the given radius, `rings` rings, and one centre vertex per cap.
inline mesh::TriangleMesh capped_tube_mesh(double radius_um, double length_um, int sides,
                                           int rings) {
  mesh::TriangleMesh tube;
  for (int ring = 0; ring < rings; ++ring) {
    const double x_um = length_um * ring / (rings - 1);
    for (int side = 0; side < sides; ++side) {
      const double angle = 2.0 * std::numbers::pi * side / sides;
      tube.positions_um.emplace_back(x_um, radius_um * std::cos(angle),
                                     radius_um * std::sin(angle));
    }
  }
  const auto at = [sides](int ring, int side) { return ring * sides + (side % sides); };
  for (int ring = 0; ring + 1 < rings; ++ring) {
    for (int side = 0; side < sides; ++side) {
      tube.triangles.push_back({at(ring, side), at(ring, side + 1), at(ring + 1, side + 1)});
      tube.triangles.push_back({at(ring, side), at(ring + 1, side + 1), at(ring + 1, side)});
    }
  }
  const int inlet_centre = rings * sides;
  const int outlet_centre = inlet_centre + 1;
  tube.positions_um.emplace_back(0.0, 0.0, 0.0);
  tube.positions_um.emplace_back(length_um, 0.0, 0.0);
  for (int side = 0; side < sides; ++side) {
    tube.triangles.push_back({inlet_centre, at(0, side + 1), at(0, side)});
    tube.triangles.push_back({outlet_centre, at(rings - 1, side), at(rings - 1, side + 1)});
  }
  return tube;
}

}  // namespace rbcsim::geometry::test_meshes
