// Test shapes for the membrane tests, all mapped from the unit icosphere: a sphere, an ellipsoid
// (axes scaled) and a biconcave disc (the Evans-Fung map). The shipped cell meshes (core/mesh
// generators) will replace these once they land; until then the test shapes live only here.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane_test {

using mesh::TriangleMesh;

inline TriangleMesh ellipsoid(int subdivisions, const Vec3& semi_axes_um) {
  auto mesh = mesh::unit_icosphere(subdivisions);
  for (auto& position : mesh.positions_um) position = position.cwiseProduct(semi_axes_um);
  return mesh;
}

inline TriangleMesh sphere(int subdivisions, double radius_um) {
  return ellipsoid(subdivisions, Vec3::Constant(radius_um));
}

// Evans-Fung discocyte: x, y -> R0 x, R0 y; z -> sign(z) R0/2 sqrt(1 - rho^2) (C0 + C2 rho^2 +
// C4 rho^4), rho^2 = x^2 + y^2 on the unit sphere (R0 = 3.91 um).
inline TriangleMesh biconcave(int subdivisions) {
  constexpr double radius_um = 3.91;
  constexpr double c0 = 0.207161;
  constexpr double c2 = 2.002558;
  constexpr double c4 = -1.122762;
  auto mesh = mesh::unit_icosphere(subdivisions);
  for (auto& p : mesh.positions_um) {
    const double rho2 = std::min(1.0, p.x() * p.x() + p.y() * p.y());
    const double height =
        0.5 * radius_um * std::sqrt(1.0 - rho2) * (c0 + c2 * rho2 + c4 * rho2 * rho2);
    p = Vec3(radius_um * p.x(), radius_um * p.y(),
             p.z() > 0 ? height : (p.z() < 0 ? -height : 0.0));
  }
  return mesh;
}

struct NamedShape {
  std::string name;
  TriangleMesh mesh;
};

// The property-test shapes: every shape at N = 3, the sphere and biconcave disc also at N = 4.
inline std::vector<NamedShape> property_test_shapes() {
  return {{"sphere3", sphere(3, 3.0)},
          {"ellipsoid3", ellipsoid(3, Vec3(4.0, 3.0, 2.0))},
          {"biconcave3", biconcave(3)},
          {"sphere4", sphere(4, 3.0)},
          {"biconcave4", biconcave(4)}};
}

inline double mean_edge_length_um(const TriangleMesh& mesh) {
  const auto topology = mesh::MeshTopology::build(mesh);
  double sum = 0.0;
  for (const auto& edge : topology.edges()) {
    sum += (mesh.positions_um[edge.vertex1] - mesh.positions_um[edge.vertex0]).norm();
  }
  return sum / static_cast<double>(topology.edge_count());
}

// Each vertex moved by a vector of uniformly random direction and a length uniform in
// [0, noise_um] (fixed seed).
inline std::vector<Vec3> with_noise(std::vector<Vec3> positions_um, double noise_um,
                                    std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (auto& p : positions_um) {
    const Vec3 direction = Vec3(gaussian(generator), gaussian(generator), gaussian(generator));
    p += noise_um * uniform(generator) * direction.normalized();
  }
  return positions_um;
}

// A small random deformation: an affine stretch (so that the cell-level measures V, DeltaA, C
// change at first order) plus vertex noise of 2 % of the mean edge (so that every element does).
inline std::vector<Vec3> small_deformation(const TriangleMesh& mesh, std::uint32_t seed) {
  const Vec3 stretch(1.01, 0.995, 0.99);
  std::vector<Vec3> positions = mesh.positions_um;
  for (auto& p : positions) p = p.cwiseProduct(stretch);
  return with_noise(std::move(positions), 0.02 * mean_edge_length_um(mesh), seed);
}

}  // namespace rbcsim::membrane_test
