#include "geometry/stl_wall.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "geometry/tube_wall.hpp"
#include "geometry/voxelise.hpp"
#include "geometry/wall_measures.hpp"
#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "test_meshes.hpp"

namespace {

using namespace rbcsim::geometry;
using rbcsim::Vec3;
namespace mesh = rbcsim::mesh;

// A general position for the ellipsoid: rotated about z then y, and shifted off the lattice.
const Eigen::Matrix3d kRotation =
    (Eigen::AngleAxisd(0.17, Vec3::UnitY()) * Eigen::AngleAxisd(0.12, Vec3::UnitZ()))
        .toRotationMatrix();
const Vec3 kCentre(0.13, -0.07, 0.21);
const Vec3 kSemiAxes(11.0, 4.0, 4.0);

// x^2/a^2 + y^2/b^2 + z^2/c^2 in the ellipsoid's own frame: < 1 inside.
double ellipsoid_level(const Vec3& point_um) {
  const Vec3 local = kRotation.transpose() * (point_um - kCentre);
  return local.cwiseQuotient(kSemiAxes).squaredNorm();
}

class AnalyticEllipsoid final : public WallShape {
 public:
  bool is_fluid(const Vec3& point_um) const override { return ellipsoid_level(point_um) < 1.0; }
  FluidBounds fluid_bounds() const override {
    return {kCentre - Vec3::Constant(11.0), kCentre + Vec3::Constant(11.0), {}};
  }
};

mesh::TriangleMesh ellipsoid_mesh(int subdivisions) {
  auto ellipsoid = mesh::unit_icosphere(subdivisions);
  for (auto& position : ellipsoid.positions_um) {
    position = kRotation * position.cwiseProduct(kSemiAxes) + kCentre;
  }
  return ellipsoid;
}

// Radius of the largest sphere about the centre inside the unit icosphere: the smallest distance
// from the centre to a face plane (the polyhedron is convex).
double inscribed_radius(const mesh::TriangleMesh& unit_sphere) {
  double radius = 1.0;
  for (const auto& triangle : unit_sphere.triangles) {
    const Vec3 normal = mesh::triangle_area_vector(unit_sphere.positions_um, triangle).normalized();
    radius = std::min(radius, normal.dot(unit_sphere.positions_um[triangle[0]]));
  }
  return radius;
}

// The icosphere's vertices lie on the ellipsoid, so the mesh (convex) lies inside it; and it
// contains the ellipsoid shrunk by the inscribed radius r of the unit icosphere (the same linear
// map takes one into the other). So the masks may differ only at nodes with r^2 <= level <= 1:
// within about one chord's sagitta of the surface.
TEST(StlWall, IcosphereEllipsoidMatchesTheAnalyticEllipsoid) {
  const int subdivisions = 4;  // 5120 triangles
  const double inner_level = std::pow(inscribed_radius(mesh::unit_icosphere(subdivisions)), 2);
  const StlWall wall(ellipsoid_mesh(subdivisions));
  const LatticeGrid grid{Vec3(-12.375, -4.875, -4.875), 0.25, 100, 40, 40};

  const auto start = std::chrono::steady_clock::now();
  const auto mesh_mask = voxelise(wall, grid);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_LT(elapsed.count(), 3.0);  // the brief's budget; it takes tens of milliseconds

  const auto analytic_mask = voxelise(AnalyticEllipsoid(), grid);
  std::size_t mismatches = 0;
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        const auto index = grid.index(i, j, k);
        if (mesh_mask[index] == analytic_mask[index]) continue;
        ++mismatches;
        const double level = ellipsoid_level(grid.node_position_um(i, j, k));
        EXPECT_GE(level, inner_level) << i << " " << j << " " << k;
        EXPECT_LE(level, 1.0) << i << " " << j << " " << k;
      }
    }
  }
  const auto fluid = fluid_node_count(analytic_mask);
  EXPECT_GT(fluid, 20000u);  // 4/3 pi 11 4 4 / 0.25^3 = 47186 nodes: the test has substance
  EXPECT_LT(mismatches, fluid / 100);
}

TEST(StlWall, InwardOrientedSurfaceGivesTheSameMask) {
  auto flipped = ellipsoid_mesh(2);
  for (auto& triangle : flipped.triangles) std::swap(triangle[1], triangle[2]);
  const LatticeGrid grid{Vec3(-12.0, -5.0, -5.0), 0.5, 49, 21, 21};
  EXPECT_EQ(voxelise(StlWall(flipped), grid), voxelise(StlWall(ellipsoid_mesh(2)), grid));
}

// Rows of this grid run exactly through the box's vertices, along its edges and face diagonals,
// and inside its faces parallel to x: the cases where a naive ray test double-counts or misses.
// The symbolic displacement (+epsilon, +epsilon^2) of every ray makes the result exact:
// 0 < x < 4 and the half-open 0 <= y < 4, 0 <= z < 4.
TEST(StlWall, RaysThroughEdgesAndVerticesOfABox) {
  const auto box = test_meshes::box_mesh(Vec3(0.0, 0.0, 0.0), Vec3(4.0, 4.0, 4.0));
  ASSERT_NEAR(mesh::enclosed_volume_um3(box), 64.0, 1e-12);
  const StlWall wall(box);
  const LatticeGrid grid{Vec3(-0.75, -1.0, -1.0), 0.5, 12, 13, 13};
  const auto mask = voxelise(wall, grid);
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        const Vec3 p = grid.node_position_um(i, j, k);
        const bool inside = p.x() > 0.0 && p.x() < 4.0 && p.y() >= 0.0 && p.y() < 4.0 &&
                            p.z() >= 0.0 && p.z() < 4.0;
        EXPECT_EQ(mask[grid.index(i, j, k)], inside ? kFluid : kSolid) << p.transpose();
      }
    }
  }
}

// An STL capillary: a tube with capped ends, open along x. The lattice spans exactly its length,
// so the end slices are fluid and an inlet profile can be imposed on them. The polygon (48 sides)
// is inscribed in the circle: it contains the circle of radius R cos(pi/48).
TEST(StlWall, CappedTubeMatchesTheAnalyticTube) {
  const double radius_um = 4.0;
  const int sides = 48;
  const StlWall wall(test_meshes::capped_tube_mesh(radius_um, 12.0, sides, 7),
                     {true, false, false});
  const TubeWall tube({2.0 * radius_um, 12.0});
  const auto grid = lattice_around(wall, 0.25);
  EXPECT_EQ(grid.nx, 48);
  const auto stl_mask = voxelise(wall, grid);
  const auto tube_mask = voxelise(tube, grid);
  const double inner_radius_um = radius_um * std::cos(std::numbers::pi / sides);
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        const auto index = grid.index(i, j, k);
        if (stl_mask[index] == tube_mask[index]) continue;
        const Vec3 p = grid.node_position_um(i, j, k);
        const double r = std::hypot(p.y(), p.z());
        EXPECT_TRUE(r >= inner_radius_um && r <= radius_um) << p.transpose();
      }
    }
  }
  EXPECT_GT(slice_fluid_area_um2(stl_mask, grid, 0), 0.9 * std::numbers::pi * 16.0);
  EXPECT_NO_THROW(poiseuille_inlet_profile(stl_mask, grid, 0));
}

TEST(StlWall, SinglePointQueries) {
  const StlWall wall(test_meshes::box_mesh(Vec3(-1.0, -2.0, -3.0), Vec3(1.0, 2.0, 3.0)));
  EXPECT_TRUE(wall.is_fluid(Vec3(0.1, 0.2, 0.3)));
  EXPECT_TRUE(wall.is_fluid(Vec3(0.99, -1.99, 2.99)));
  EXPECT_FALSE(wall.is_fluid(Vec3(1.01, 0.0, 0.0)));
  EXPECT_FALSE(wall.is_fluid(Vec3(0.0, 2.5, 0.0)));
  EXPECT_FALSE(wall.is_fluid(Vec3(-5.0, 0.0, 0.0)));
  const auto bounds = wall.fluid_bounds();
  EXPECT_EQ(bounds.min_um, Vec3(-1.0, -2.0, -3.0));
  EXPECT_EQ(bounds.max_um, Vec3(1.0, 2.0, 3.0));
}

TEST(StlWall, RejectsSurfacesThatAreNotClosed) {
  auto open_box = test_meshes::box_mesh(Vec3::Zero(), Vec3::Ones());
  open_box.triangles.pop_back();
  try {
    StlWall wall(open_box, {}, "wall.stl");
    FAIL() << "an open surface was accepted";
  } catch (const rbcsim::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("wall.stl: the wall surface must be closed"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(StlWall(mesh::TriangleMesh{}), rbcsim::InputError);
  auto broken = test_meshes::box_mesh(Vec3::Zero(), Vec3::Ones());
  broken.positions_um[3].x() = std::nan("");
  EXPECT_THROW(StlWall(std::move(broken)), rbcsim::InputError);
}

}  // namespace
