// The wall's short-range push (wall_repulsion.hpp) against its force law, by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "cases/wall_repulsion.hpp"
#include "common/errors.hpp"

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

// The barrier: the pressure law's push at half the range, (r/d - 1)^2 of a quarter of its contact
// push elsewhere, nothing at and beyond the range, and floored at a hundredth of the range.
TEST(WallRepulsion, TheBarrierAgreesWithThePressureLawAtHalfItsRangeAndGrowsCloserIn) {
  const WallRepulsion pressure{8.0, 0.5};
  const WallRepulsion barrier{8.0, 0.5, WallLaw::barrier};
  EXPECT_NEAR(wall_push_pN(barrier, 0.25), wall_push_pN(pressure, 0.25), 1e-12);  // 2 pN
  EXPECT_NEAR(wall_push_pN(barrier, 0.1), 2.0 * 16.0, 1e-12);                     // (5 - 1)^2 = 16
  EXPECT_NEAR(wall_push_pN(barrier, 0.4), 2.0 * 0.0625, 1e-12);                   // (1.25 - 1)^2
  EXPECT_EQ(wall_push_pN(barrier, 0.5), 0.0);
  EXPECT_NEAR(wall_push_pN(barrier, -0.2), 2.0 * 99.0 * 99.0, 1e-9);
  EXPECT_NEAR(wall_push_pN(barrier, 0.004), 2.0 * 99.0 * 99.0, 1e-9);
}

// A vertex pressed outward by 40 pN (a cell squeezed between neighbours whose contact push is
// capped at 50 pN a vertex): the pressure law's 8 pN at contact cannot hold it, so it reaches the
// wall; the barrier holds it where the push balances, r / (1 + sqrt(40 / 2)) from the wall.
TEST(WallRepulsion, TheBarrierHoldsAVertexThePressureLawLetsThrough) {
  const double squeeze_pN = 40.0;
  const auto resting_distance = [&](const WallRepulsion& repulsion) {
    double d = 0.5;  // relaxed towards the wall while the squeeze wins: the wall's push only grows
    for (int i = 0; i < 200000 && d > 0.0; ++i) {
      d -= 1e-6 * (squeeze_pN - wall_push_pN(repulsion, d));
    }
    return d;
  };
  EXPECT_LE(resting_distance({8.0, 0.5}), 0.0);
  EXPECT_NEAR(resting_distance({8.0, 0.5, WallLaw::barrier}), 0.5 / (1.0 + std::sqrt(20.0)), 1e-6);
}

// suspension.wall_law's names, both ways, and one clear error for any other.
TEST(WallRepulsion, LawsAreChosenByName) {
  for (const auto& name : wall_law_names()) EXPECT_EQ(wall_law_name(wall_law_named(name)), name);
  EXPECT_EQ(wall_law_named("barrier"), WallLaw::barrier);
  EXPECT_THROW((void)wall_law_named("wall"), InputError);
}

}  // namespace
}  // namespace rbcsim::cases
