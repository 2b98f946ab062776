// Which nodes a point reaches and with what weight: on and between nodes (closed-form kernel
// values), across periodic boundaries, at the edge of a non-periodic grid, and next to a wall.
#include "ibm/interpolation_stencil.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "common/errors.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::ibm::find_delta_kernel;
using rbcsim::ibm::GridView;
using rbcsim::ibm::InterpolationStencil;
using rbcsim::ibm::node_count;
using rbcsim::ibm::node_index;

using WeightByNode = std::map<std::size_t, double>;

WeightByNode stencil_of_point(const std::string& kernel, const GridView& grid, const Vec3& position,
                              const std::uint8_t* solid_mask = nullptr) {
  InterpolationStencil stencil;
  const std::vector<Vec3> positions{position};
  stencil.build(find_delta_kernel(kernel), grid, positions, solid_mask);
  WeightByNode weights;
  for (std::size_t slot = 0; slot < stencil.nodes(0).size(); ++slot) {
    weights[stencil.nodes(0)[slot]] += stencil.weights(0)[slot];
  }
  return weights;
}

// Expected weights from per-axis lists of (node number along the axis, 1D weight).
using AxisWeights = std::vector<std::pair<int, double>>;
WeightByNode product_weights(const GridView& grid, const AxisWeights& x, const AxisWeights& y,
                             const AxisWeights& z) {
  WeightByNode weights;
  for (const auto& [k, weight_z] : z) {
    for (const auto& [j, weight_y] : y) {
      for (const auto& [i, weight_x] : x) {
        weights[node_index(grid, i, j, k)] += weight_x * weight_y * weight_z;
      }
    }
  }
  return weights;
}

void expect_same_weights(const WeightByNode& actual, const WeightByNode& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (const auto& [node, weight] : expected) {
    ASSERT_TRUE(actual.contains(node)) << "node " << node;
    EXPECT_NEAR(actual.at(node), weight, 1e-15) << "node " << node;
  }
}

constexpr GridView kPeriodicGrid{8, 6, 5, true, true, true};

TEST(InterpolationStencil, Phi2OnANodeTouchesOnlyThatNode) {
  expect_same_weights(stencil_of_point("phi2", kPeriodicGrid, Vec3(3, 2, 1)),
                      {{node_index(kPeriodicGrid, 3, 2, 1), 1.0}});
}

TEST(InterpolationStencil, Phi2MidwaySharesEquallyAmongEightNodes) {
  const AxisWeights x{{3, 0.5}, {4, 0.5}}, y{{2, 0.5}, {3, 0.5}}, z{{1, 0.5}, {2, 0.5}};
  expect_same_weights(stencil_of_point("phi2", kPeriodicGrid, Vec3(3.5, 2.5, 1.5)),
                      product_weights(kPeriodicGrid, x, y, z));
}

TEST(InterpolationStencil, Phi3OnANodeGivesTwoThirdsAndOneSixths) {
  // phi3(0) = (1 + 1) / 3, phi3(1) = (5 - 3 - 1) / 6.
  const AxisWeights x{{2, 1 / 6.0}, {3, 2 / 3.0}, {4, 1 / 6.0}};
  const AxisWeights y{{1, 1 / 6.0}, {2, 2 / 3.0}, {3, 1 / 6.0}};
  const AxisWeights z{{0, 1 / 6.0}, {1, 2 / 3.0}, {2, 1 / 6.0}};
  expect_same_weights(stencil_of_point("phi3", kPeriodicGrid, Vec3(3, 2, 1)),
                      product_weights(kPeriodicGrid, x, y, z));
}

TEST(InterpolationStencil, Phi4OnANodeGivesOneHalfAndOneQuarters) {
  // phi4(0) = (3 + 1) / 8, phi4(1) = (3 - 1) / 8, phi4(2) = 0 (that node is left out).
  const AxisWeights x{{2, 0.25}, {3, 0.5}, {4, 0.25}};
  const AxisWeights y{{1, 0.25}, {2, 0.5}, {3, 0.25}};
  const AxisWeights z{{0, 0.25}, {1, 0.5}, {2, 0.25}};
  expect_same_weights(stencil_of_point("phi4", kPeriodicGrid, Vec3(3, 2, 1)),
                      product_weights(kPeriodicGrid, x, y, z));
}

TEST(InterpolationStencil, PeriodicAxesWrapNodesAndPointsOutsideTheBox) {
  // x near the low face, y near the high face (node 6 is node 0), z outside the box (-0.4).
  const AxisWeights x{{0, 0.8}, {1, 0.2}}, y{{5, 0.3}, {0, 0.7}}, z{{4, 0.4}, {0, 0.6}};
  expect_same_weights(stencil_of_point("phi2", kPeriodicGrid, Vec3(0.2, 5.7, -0.4)),
                      product_weights(kPeriodicGrid, x, y, z));
}

TEST(InterpolationStencil, NodesOutsideANonPeriodicAxisAreDroppedAndTheRestRenormalised) {
  const GridView grid{8, 8, 8, false, true, true};
  const auto& phi4 = find_delta_kernel("phi4");
  // x = 0.25 reaches nodes -1..2; node -1 does not exist.
  const double kept = phi4.weight_1d(0.25) + phi4.weight_1d(0.75) + phi4.weight_1d(1.75);
  const AxisWeights x{{0, phi4.weight_1d(0.25) / kept},
                      {1, phi4.weight_1d(0.75) / kept},
                      {2, phi4.weight_1d(1.75) / kept}};
  const AxisWeights y{{3, 0.25}, {4, 0.5}, {5, 0.25}}, z{{0, 0.25}, {1, 0.5}, {2, 0.25}};
  const auto weights = stencil_of_point("phi4", grid, Vec3(0.25, 4, 1));
  expect_same_weights(weights, product_weights(grid, x, y, z));
  for (const auto& [node, weight] : weights) EXPECT_LT(node, node_count(grid));
}

TEST(InterpolationStencil, SolidNodesAreDroppedAndTheRestRenormalised) {
  // A wall: the plane k = 0 is solid.
  const GridView grid{6, 6, 6, true, true, false};
  std::vector<std::uint8_t> solid(node_count(grid), 0);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) solid[node_index(grid, i, j, 0)] = 1;
  }
  const auto& phi3 = find_delta_kernel("phi3");
  // z = 1.2 reaches nodes 0 (solid), 1 and 2.
  const double kept = phi3.weight_1d(0.2) + phi3.weight_1d(0.8);
  const AxisWeights z{{1, phi3.weight_1d(0.2) / kept}, {2, phi3.weight_1d(0.8) / kept}};
  const AxisWeights x{{2, phi3.weight_1d(0.5)}, {3, phi3.weight_1d(0.5)}};  // x = 2.5
  const AxisWeights y{{2, 1 / 6.0}, {3, 2 / 3.0}, {4, 1 / 6.0}};
  const auto weights = stencil_of_point("phi3", grid, Vec3(2.5, 3, 1.2), solid.data());
  expect_same_weights(weights, product_weights(grid, x, y, z));
  double total = 0.0;
  for (const auto& [node, weight] : weights) total += weight;
  EXPECT_NEAR(total, 1.0, 1e-15);
}

TEST(InterpolationStencil, APointWithNoFluidNodeInReachIsARuntimeFailureNamingIt) {
  const GridView grid{6, 6, 6, false, false, false};
  std::vector<std::uint8_t> solid(node_count(grid), 0);
  for (int i = 0; i < 3; ++i) solid[node_index(grid, i, 3, 3)] = 1;
  const auto& phi2 = find_delta_kernel("phi2");
  InterpolationStencil stencil;
  const std::vector<std::vector<Vec3>> bad_cases{
      {Vec3(2, 2, 2), Vec3(1, 3, 3)},     // point 1 sits on a solid node
      {Vec3(2, 2, 2), Vec3(-1.5, 2, 2)},  // point 1 is beyond the grid's low x face
      {Vec3(2, 2, 2), Vec3(2, NAN, 2)}};  // point 1's position is not a number
  for (const auto& positions : bad_cases) {
    try {
      stencil.build(phi2, grid, positions, solid.data());
      FAIL() << "no error for point at x = " << positions[1].x();
    } catch (const rbcsim::RuntimeFailure& error) {
      EXPECT_NE(std::string(error.what()).find("point 1 "), std::string::npos) << error.what();
    }
  }
}

TEST(InterpolationStencil, RebuildingForAsManyPointsReusesTheStorage) {
  const auto& phi4 = find_delta_kernel("phi4");
  InterpolationStencil stencil;
  std::vector<Vec3> positions{Vec3(1.5, 2, 3), Vec3(4, 4.25, 0.5)};
  stencil.build(phi4, kPeriodicGrid, positions);
  const double* weights_before = stencil.weights(0).data();
  const std::size_t* nodes_before = stencil.nodes(0).data();
  positions[0] += Vec3(0.3, -0.2, 0.1);
  stencil.build(phi4, kPeriodicGrid, positions);
  EXPECT_EQ(stencil.weights(0).data(), weights_before);
  EXPECT_EQ(stencil.nodes(0).data(), nodes_before);
  EXPECT_EQ(stencil.point_count(), 2u);
}

}  // namespace
