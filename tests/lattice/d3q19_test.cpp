#include "lattice/d3q19.hpp"

#include "common/errors.hpp"
#include "lattice/lattice_grid.hpp"

#include <gtest/gtest.h>

namespace rbcsim::lattice {
namespace {

// The lattice tensors an isotropic second-order scheme needs: sum w = 1, sum w c = 0,
// sum w c_a c_b = c_s^2 delta_ab, sum w c_a c_b c_c = 0.
TEST(D3Q19, WeightsHaveTheIsotropicMoments) {
  double weight_sum = 0.0;
  double first[3] = {0, 0, 0};
  double second[3][3] = {};
  for (int i = 0; i < kDirections; ++i) {
    const auto& c = kVelocities[i];
    weight_sum += kWeights[i];
    for (int a = 0; a < 3; ++a) {
      first[a] += kWeights[i] * c[a];
      for (int b = 0; b < 3; ++b) {
        second[a][b] += kWeights[i] * c[a] * c[b];
      }
    }
  }
  EXPECT_NEAR(weight_sum, 1.0, 1e-15);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(first[a], 0.0, 1e-15);
    for (int b = 0; b < 3; ++b) {
      EXPECT_NEAR(second[a][b], a == b ? 1.0 / 3.0 : 0.0, 1e-15);
    }
  }
  for (int i = 0; i < kDirections; ++i) {
    const int o = kOpposite[i];
    EXPECT_EQ(kOpposite[o], i);
    EXPECT_EQ(kWeights[o], kWeights[i]);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(kVelocities[o][a], -kVelocities[i][a]);
    }
  }
}

TEST(D3Q19, EquilibriumHasTheRequestedMoments) {
  const double density = 1.03;
  const std::array<double, 3> velocity = {0.04, -0.02, 0.01};
  double mass = 0.0;
  std::array<double, 3> momentum = {0.0, 0.0, 0.0};
  double momentum_flux_xy = 0.0;
  for (int i = 0; i < kDirections; ++i) {
    const double f = equilibrium(i, density, velocity);
    mass += f;
    for (int a = 0; a < 3; ++a) {
      momentum[a] += f * kVelocities[i][a];
    }
    momentum_flux_xy += f * kVelocities[i][0] * kVelocities[i][1];
  }
  EXPECT_NEAR(mass, density, 1e-15);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(momentum[a], density * velocity[a], 1e-15);
  }
  EXPECT_NEAR(momentum_flux_xy, density * velocity[0] * velocity[1], 1e-15);
}

TEST(LatticeGrid, IndexesXFastestAndWrapsNeighbours) {
  const LatticeGrid grid(4, 3, 2);
  EXPECT_EQ(grid.node_count(), 24u);
  EXPECT_EQ(grid.index(1, 2, 1), 1u + 4u * (2u + 3u * 1u));
  EXPECT_EQ(grid.coordinates(grid.index(3, 1, 1)), (std::array<int, 3>{3, 1, 1}));
  EXPECT_EQ(grid.periodic_neighbour(grid.index(0, 0, 0), {-1, -1, -1}), grid.index(3, 2, 1));
  EXPECT_EQ(grid.periodic_neighbour(grid.index(3, 2, 1), {1, 1, 1}), grid.index(0, 0, 0));
}

TEST(LatticeGrid, RejectsEmptyExtents) { EXPECT_THROW(LatticeGrid(0, 3, 3), InputError); }

}  // namespace
}  // namespace rbcsim::lattice
