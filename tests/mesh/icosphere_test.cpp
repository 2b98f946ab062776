#include "mesh/icosphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"

namespace {

class IcosphereLevels : public ::testing::TestWithParam<int> {};

TEST_P(IcosphereLevels, CountsOrientationAndSphereLimit) {
  const int level = GetParam();
  const auto mesh = rbcsim::mesh::unit_icosphere(level);
  const auto topology = rbcsim::mesh::MeshTopology::build(mesh);
  const auto power = static_cast<std::size_t>(std::pow(4, level));
  EXPECT_EQ(topology.vertex_count(), 10 * power + 2);
  EXPECT_EQ(topology.edge_count(), 30 * power);
  EXPECT_EQ(topology.triangle_count(), 20 * power);
  for (const auto& position : mesh.positions_um) EXPECT_NEAR(position.norm(), 1.0, 1e-14);
  // Inscribed polyhedron: volume below the sphere's, converging to it at second order in the edge
  // length, which halves per level. The constant 2.5 bounds error * 4^level over levels 0..4
  // (the icosahedron's chord error is 1.65, and the ratio per level tends to 4 from below).
  const double volume = rbcsim::mesh::enclosed_volume_um3(mesh);
  const double sphere_volume = 4.0 / 3.0 * std::numbers::pi;
  EXPECT_GT(volume, 0.0);
  EXPECT_LT(volume, sphere_volume);
  EXPECT_LT(sphere_volume - volume, 2.5 * std::pow(4.0, -level));
}

INSTANTIATE_TEST_SUITE_P(Levels, IcosphereLevels, ::testing::Values(0, 1, 2, 3, 4));

}  // namespace
