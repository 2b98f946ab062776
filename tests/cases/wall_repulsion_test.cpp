// The wall's short-range push (wall_repulsion.hpp) against its force law, by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "cases/wall_repulsion.hpp"

namespace rbcsim::cases {
namespace {

// A tube of radius 5 um; range 0.5 um, 8 pN at contact.
TEST(WallRepulsion, PushesAlongTheInwardRadiusWithinItsRangeOnly) {
  const auto radius = [](double) { return 5.0; };
  const WallRepulsion repulsion{8.0, 0.5};
  const double c = std::sqrt(0.5);
  const std::vector<Vec3> positions{
      {1.0, 4.75 * c, 4.75 * c},  // 0.25 um from the wall: 8 (1 - 0.5)^2 = 2 pN
      {2.0, 0.0, -4.6},           // 0.4 um: 8 (0.2)^2 = 0.32 pN, along +z
      {3.0, 4.5, 0.0},            // at the range: nothing
      {4.0, 0.0, 0.0},            // on the axis: nothing
  };
  std::vector<Vec3> forces(positions.size(), Vec3(1.0, 0.0, 0.0));
  add_tube_wall_repulsion(positions, radius, repulsion, forces);
  EXPECT_LT((forces[0] - Vec3(1.0, -2.0 * c, -2.0 * c)).norm(), 1e-12);
  EXPECT_LT((forces[1] - Vec3(1.0, 0.0, 0.32)).norm(), 1e-12);
  EXPECT_LT((forces[2] - Vec3(1.0, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((forces[3] - Vec3(1.0, 0.0, 0.0)).norm(), 1e-15);
}

TEST(WallRepulsion, FollowsTheLocalRadiusAndSaturatesAtContact) {
  const auto narrowing = [](double x_um) { return 5.0 - 0.1 * x_um; };  // 4 um at x = 10
  std::vector<Vec3> positions{{10.0, 3.9, 0.0}, {10.0, 4.2, 0.0}};
  std::vector<Vec3> forces(2, Vec3::Zero());
  add_tube_wall_repulsion(positions, narrowing, {8.0, 0.5}, forces);
  EXPECT_NEAR(forces[0].y(), -8.0 * 0.8 * 0.8, 1e-12);
  EXPECT_NEAR(forces[1].y(), -8.0, 1e-12);  // beyond the wall: the contact force
  EXPECT_THROW(add_tube_wall_repulsion(positions, narrowing, {8.0, 0.0}, forces),
               std::invalid_argument);
}

// Walls at y = -3 and +3 um: each vertex pushed away from the nearer one, along y only.
TEST(WallRepulsion, PushesOffTheNearerOfTwoFlatWalls) {
  const std::vector<Vec3> positions{
      {1.0, 2.75, 7.0},   // 0.25 um below the top wall: 2 pN down
      {2.0, -2.9, -1.0},  // 0.1 um above the bottom wall: 8 (0.8)^2 pN up
      {3.0, 2.5, 0.0},    // at the range: nothing
      {4.0, 0.0, 0.0},    // mid-gap: nothing
  };
  std::vector<Vec3> forces(positions.size(), Vec3(1.0, 0.0, 0.0));
  add_wall_repulsion(
      positions, [](const Vec3& p) { return slab_wall_distance(p, 3.0); }, {8.0, 0.5}, forces);
  EXPECT_LT((forces[0] - Vec3(1.0, -2.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((forces[1] - Vec3(1.0, 8.0 * 0.8 * 0.8, 0.0)).norm(), 1e-12);
  EXPECT_LT((forces[2] - Vec3(1.0, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((forces[3] - Vec3(1.0, 0.0, 0.0)).norm(), 1e-15);
}

}  // namespace
}  // namespace rbcsim::cases
