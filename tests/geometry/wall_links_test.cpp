#include "geometry/wall_links.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "geometry/capillary_wall.hpp"
#include "geometry/channel_wall.hpp"
#include "geometry/stl_wall.hpp"
#include "geometry/tube_wall.hpp"
#include "geometry/voxelise.hpp"
#include "lattice/d3q19.hpp"
#include "test_meshes.hpp"

namespace {

using namespace rbcsim::geometry;
using rbcsim::Vec3;
using rbcsim::lattice::WallLink;

Vec3 link_vector(int direction) {
  const auto& c = rbcsim::lattice::kVelocities[direction];
  return Vec3(c[0], c[1], c[2]);
}

Vec3 node_position_um(const LatticeGrid& grid, std::size_t node) {
  const auto i = static_cast<int>(node % static_cast<std::size_t>(grid.nx));
  const auto j = static_cast<int>(node / static_cast<std::size_t>(grid.nx) % grid.ny);
  const auto k = static_cast<int>(node / (static_cast<std::size_t>(grid.nx) * grid.ny));
  return grid.node_position_um(i, j, k);
}

// Every link from a fluid node to a solid neighbour (periodic wrap), counted directly.
std::size_t fluid_to_solid_links(const LatticeGrid& grid, const SolidMask& mask) {
  std::size_t count = 0;
  const auto wrap = [](int value, int extent) { return ((value % extent) + extent) % extent; };
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        if (mask[grid.index(i, j, k)] != kFluid) {
          continue;
        }
        for (int d = 1; d < rbcsim::lattice::kDirections; ++d) {
          const auto& c = rbcsim::lattice::kVelocities[d];
          count += mask[grid.index(wrap(i + c[0], grid.nx), wrap(j + c[1], grid.ny),
                                   wrap(k + c[2], grid.nz))] == kSolid;
        }
      }
    }
  }
  return count;
}

struct ShapeLinks {
  LatticeGrid grid;
  SolidMask mask;
  std::vector<WallLink> links;
};

// Voxelises the shape on `grid` and lists its wall links: one per fluid-to-solid link.
ShapeLinks wall_links_on(const WallShape& shape, const LatticeGrid& grid) {
  ShapeLinks result{grid, voxelise(shape, grid), {}};
  result.links = wall_link_fractions(shape, grid, result.mask);
  EXPECT_EQ(result.links.size(), fluid_to_solid_links(grid, result.mask));
  EXPECT_FALSE(result.links.empty());
  return result;
}

// Where the segment p + t c (t in [0, 1]) leaves the disc y^2 + z^2 < R^2: the root of
// |p_perp + t c_perp|^2 = R^2 that lies in (0, 1].
double circle_exit_fraction(const Vec3& p, const Vec3& c, double radius) {
  const double a = c.y() * c.y() + c.z() * c.z();
  const double b = 2.0 * (p.y() * c.y() + p.z() * c.z());
  const double constant = p.y() * p.y() + p.z() * p.z() - radius * radius;
  return (-b + std::sqrt(b * b - 4.0 * a * constant)) / (2.0 * a);
}

TEST(WallLinks, TubeFractionsAreTheCircleCrossings) {
  const double dx_um = 0.5;
  const TubeWall tube({7.3, 3.0});
  LatticeGrid shifted = lattice_around(tube, dx_um);
  shifted.origin_um += dx_um * Vec3(0.0, 0.31, -0.12);
  const auto [grid, mask, links] = wall_links_on(tube, shifted);
  for (const WallLink& link : links) {
    ASSERT_EQ(mask[link.node], kFluid);
    const double expected = circle_exit_fraction(node_position_um(grid, link.node) / dx_um,
                                                 link_vector(link.direction), 3.65 / dx_um);
    EXPECT_GT(link.fraction, 0.0);
    EXPECT_LE(link.fraction, 1.0);
    EXPECT_NEAR(link.fraction, expected, kWallFractionTolerance);
  }
  // Listed by node, then direction.
  EXPECT_TRUE(std::is_sorted(links.begin(), links.end(), [](const auto& a, const auto& b) {
    return a.node != b.node ? a.node < b.node : a.direction < b.direction;
  }));
}

TEST(WallLinks, ChannelPlatesOffTheHalfwayPositions) {
  const double dx_um = 0.5;
  const ChannelWall channel({5.0, 2.0, 1.5});
  LatticeGrid shifted = lattice_around(channel, dx_um);
  shifted.origin_um.y() += 0.2 * dx_um;  // plates now 0.3 dx past the last fluid node at the top
  const auto [grid, mask, links] = wall_links_on(channel, shifted);
  for (const WallLink& link : links) {
    const int cy = rbcsim::lattice::kVelocities[link.direction][1];
    ASSERT_NE(cy, 0);
    const double plate_um = cy * 2.5;
    const double expected = (plate_um - node_position_um(grid, link.node).y()) / (cy * dx_um);
    EXPECT_NEAR(link.fraction, expected, kWallFractionTolerance);
    EXPECT_NEAR(link.fraction, cy > 0 ? 0.3 : 0.7, 1e-9);
  }
}

TEST(WallLinks, CapillaryWallPointsLieOnTheLumen) {
  CapillaryParameters parameters;
  parameters.length_um = 12.0;
  parameters.inlet_diameter_um = 6.0;
  parameters.outlet_diameter_um = 6.0;
  parameters.throat_diameter_um = 3.5;
  const CapillaryWall capillary(parameters);
  const double dx_um = 0.4;
  const auto [grid, mask, links] = wall_links_on(capillary, lattice_around(capillary, dx_um));
  const double link_um = std::sqrt(2.0) * dx_um;
  for (const WallLink& link : links) {
    const Vec3 wall_um =
        node_position_um(grid, link.node) + link.fraction * dx_um * link_vector(link.direction);
    const double radial_um = std::hypot(wall_um.y(), wall_um.z());
    // Within the bisection tolerance along the link, times the wall's steepest slope (< 1 here).
    EXPECT_NEAR(radial_um, capillary.lumen_radius_um(wall_um.x()),
                2.0 * kWallFractionTolerance * link_um);
  }
}

// The first face a link leaves the box [low, high] through.
double box_exit_fraction(const Vec3& p, const Vec3& c, const Vec3& low, const Vec3& high) {
  double fraction = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (c[axis] > 0.0) {
      fraction = std::min(fraction, (high[axis] - p[axis]) / c[axis]);
    } else if (c[axis] < 0.0) {
      fraction = std::min(fraction, (low[axis] - p[axis]) / c[axis]);
    }
  }
  return fraction;
}

TEST(WallLinks, StlBoxFacesByTheSameBisection) {
  const Vec3 low(-2.03, -1.61, -1.27);
  const Vec3 high(2.11, 1.43, 1.36);
  const StlWall box(rbcsim::geometry::test_meshes::box_mesh(low, high));
  const double dx_um = 0.5;
  const auto [grid, mask, links] = wall_links_on(box, lattice_around(box, dx_um));
  for (const WallLink& link : links) {
    const double expected =
        box_exit_fraction(node_position_um(grid, link.node) / dx_um, link_vector(link.direction),
                          low / dx_um, high / dx_um);
    EXPECT_NEAR(link.fraction, expected, kWallFractionTolerance);
  }
}

// A node the mask calls solid inside the lumen (another voxelisation rule): the shape has no wall
// along its links, which take the half-way fraction.
TEST(WallLinks, LinksTheShapeDoesNotCrossAreHalfway) {
  const TubeWall tube({6.0, 2.0});
  const LatticeGrid grid = lattice_around(tube, 0.5);
  SolidMask mask = voxelise(tube, grid);
  const std::size_t centre = grid.index(1, grid.ny / 2, grid.nz / 2);
  ASSERT_EQ(mask[centre], kFluid);
  mask[centre] = kSolid;
  std::size_t into_centre = 0;
  for (const WallLink& link : wall_link_fractions(tube, grid, mask)) {
    const auto& c = rbcsim::lattice::kVelocities[link.direction];
    const Vec3 end_um = node_position_um(grid, link.node) + 0.5 * Vec3(c[0], c[1], c[2]);
    if ((end_um - node_position_um(grid, centre)).norm() < 1e-12) {
      EXPECT_EQ(link.fraction, rbcsim::lattice::kHalfwayFraction);
      ++into_centre;
    }
  }
  EXPECT_EQ(into_centre, 18u);
}

TEST(WallLinks, MaskOfTheWrongSizeIsRefused) {
  const TubeWall tube({6.0, 2.0});
  const LatticeGrid grid = lattice_around(tube, 0.5);
  EXPECT_THROW(wall_link_fractions(tube, grid, SolidMask(3, kFluid)), std::invalid_argument);
}

}  // namespace
