// Topology and geometry measures on solids whose answers are known in closed form.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"
#include "mesh/transform.hpp"
#include "mesh_test_support.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::mesh::MeshTopology;
using rbcsim::mesh::TriangleMesh;

using rbcsim::mesh::testing::octahedron;

TEST(Topology, OctahedronCountsAndEdgeOrientation) {
  const auto mesh = octahedron();
  const auto topology = MeshTopology::build(mesh);
  EXPECT_EQ(topology.vertex_count(), 6u);
  EXPECT_EQ(topology.edge_count(), 12u);
  EXPECT_EQ(topology.triangle_count(), 8u);
  EXPECT_EQ(topology.euler_characteristic(), 2);
  for (const auto& edge : topology.edges()) {
    // triangle0 must run vertex0 -> vertex1 and contain wing0.
    const auto& t0 = mesh.triangles[edge.triangle0];
    bool found = false;
    for (int k = 0; k < 3; ++k) {
      found |=
          t0[k] == edge.vertex0 && t0[(k + 1) % 3] == edge.vertex1 && t0[(k + 2) % 3] == edge.wing0;
    }
    EXPECT_TRUE(found);
  }
  // Every vertex of an octahedron has 4 triangles and 4 edges.
  for (std::size_t v = 0; v < 6; ++v) {
    EXPECT_EQ(topology.vertex_triangle_offsets()[v + 1] - topology.vertex_triangle_offsets()[v], 4);
    EXPECT_EQ(topology.vertex_edge_offsets()[v + 1] - topology.vertex_edge_offsets()[v], 4);
  }
}

TEST(Topology, RejectsOpenNonManifoldAndInconsistentMeshes) {
  auto open = octahedron();
  open.triangles.pop_back();
  EXPECT_THROW(MeshTopology::build(open), std::invalid_argument);

  auto flipped_one = octahedron();
  std::swap(flipped_one.triangles[0][0], flipped_one.triangles[0][1]);
  EXPECT_THROW(MeshTopology::build(flipped_one), std::invalid_argument);

  auto fin = octahedron();  // a third triangle on edge (0, 2)
  fin.positions_um.push_back(Vec3(2, 2, 2));
  fin.triangles.push_back({0, 2, 6});
  fin.triangles.push_back({2, 0, 6});
  EXPECT_THROW(MeshTopology::build(fin), std::invalid_argument);
}

TEST(Geometry, OctahedronAreaVolumeAndDihedralAngles) {
  const auto mesh = octahedron();
  const auto topology = MeshTopology::build(mesh);
  const double edge_um = std::sqrt(2.0);
  EXPECT_NEAR(rbcsim::mesh::surface_area_um2(mesh), 2.0 * std::sqrt(3.0) * edge_um * edge_um,
              1e-12);
  EXPECT_NEAR(rbcsim::mesh::enclosed_volume_um3(mesh), 4.0 / 3.0, 1e-12);
  // Angle between outward normals of adjacent faces: pi minus the interior dihedral angle
  // arccos(-1/3), i.e. arccos(1/3), positive because the octahedron is convex.
  const double expected_angle = std::acos(1.0 / 3.0);
  for (const auto& edge : topology.edges()) {
    EXPECT_NEAR(rbcsim::mesh::signed_dihedral_angle_rad(mesh.positions_um, edge), expected_angle,
                1e-12);
  }
  const auto sums = rbcsim::mesh::curvature_sums(mesh.positions_um, topology);
  EXPECT_NEAR(sums.signed_um, 12 * 0.5 * edge_um * expected_angle, 1e-12);
  EXPECT_NEAR(sums.absolute_um, sums.signed_um, 1e-12);
}

// A face with corners on the half-axes a, b, c has area sqrt(a^2 b^2 + b^2 c^2 + c^2 a^2) / 2:
// sqrt(3) / 2 on the unit octahedron, the reference here.
TEST(Geometry, AreaStrainOfAnOctahedronAgainstTheUnitOne) {
  const auto mesh = octahedron();
  const std::vector<double> reference(8, std::sqrt(3.0) / 2.0);
  const auto strain_of = [&](std::vector<Vec3> positions) {
    return rbcsim::mesh::area_strain(positions, mesh.triangles, reference);
  };
  std::vector<Vec3> moved = mesh.positions_um;
  const Eigen::AngleAxisd turn(0.7, Vec3(1.0, 2.0, -0.5).normalized());
  for (auto& position : moved) position = turn * position + Vec3(7.0, -2.0, 3.0);
  EXPECT_NEAR(strain_of(moved).total_relative_change, 0.0, 1e-15);
  EXPECT_NEAR(strain_of(moved).max_abs_triangle_deviation, 0.0, 1e-15);

  std::vector<Vec3> scaled = mesh.positions_um;
  for (auto& position : scaled) position *= 0.9;
  EXPECT_NEAR(strain_of(scaled).total_relative_change, 0.81 - 1.0, 1e-15);
  EXPECT_NEAR(strain_of(scaled).max_abs_triangle_deviation, 0.19, 1e-15);  // compressed: |d|

  // Only the +x corner pulled out to 2: its four faces have area sqrt(9) / 2 = 1.5, the other
  // four keep theirs.
  std::vector<Vec3> pulled = mesh.positions_um;
  pulled[0].x() = 2.0;
  const double face_deviation = 1.5 / (std::sqrt(3.0) / 2.0) - 1.0;
  EXPECT_NEAR(strain_of(pulled).max_abs_triangle_deviation, face_deviation, 1e-15);
  EXPECT_NEAR(strain_of(pulled).total_relative_change, face_deviation / 2.0, 1e-15);

  EXPECT_THROW(rbcsim::mesh::area_strain(pulled, mesh.triangles, std::vector<double>(7, 1.0)),
               std::invalid_argument);
  EXPECT_THROW(rbcsim::mesh::area_strain(pulled, mesh.triangles, std::vector<double>(8, 0.0)),
               std::invalid_argument);
}

TEST(Geometry, InsideOutMeshHasNegativeVolumeAndAngles) {
  auto mesh = octahedron();
  for (auto& triangle : mesh.triangles) std::swap(triangle[1], triangle[2]);
  const auto topology = MeshTopology::build(mesh);
  EXPECT_NEAR(rbcsim::mesh::enclosed_volume_um3(mesh), -4.0 / 3.0, 1e-12);
  for (const auto& edge : topology.edges()) {
    EXPECT_LT(rbcsim::mesh::signed_dihedral_angle_rad(mesh.positions_um, edge), 0.0);
  }
}

TEST(Geometry, ConcaveEdgeHasNegativeAngle) {
  // Two triangles folded into a valley: the edge along x, wings raised above the edge.
  const std::vector<Vec3> positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0.3),
                                       Vec3(0.5, -1, 0.3)};
  const rbcsim::mesh::Edge valley{0, 1, 2, 3, 0, 1};
  EXPECT_NEAR(rbcsim::mesh::signed_dihedral_angle_rad(positions, valley), -2.0 * std::atan(0.3),
              1e-12);
}

TEST(Geometry, ReducedVolumeOfSphereIsOne) {
  const double radius = 2.5;
  const double area = 4.0 * std::numbers::pi * radius * radius;
  const double volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  EXPECT_NEAR(rbcsim::mesh::reduced_volume(area, volume), 1.0, 1e-14);
}

}  // namespace

namespace {

TEST(Transform, RoundingToSinglePrecisionRoundsEveryCoordinate) {
  // 162 points with coordinates no float holds exactly; GCC 12.2 at -O2 vectorises the plain
  // `p[a] = static_cast<float>(p[a])` loop into one that keeps x and y unrounded.
  rbcsim::mesh::TriangleMesh mesh;
  for (int i = 0; i < 162; ++i) {
    mesh.positions_um.emplace_back(0.1 * i + 1e-9, 0.3 * i + 1e-10, 0.7 / (i + 1));
  }
  rbcsim::mesh::round_to_single_precision(mesh);
  for (const auto& p : mesh.positions_um) {
    for (int axis = 0; axis < 3; ++axis) {
      volatile float as_float = static_cast<float>(p[axis]);
      EXPECT_EQ(static_cast<double>(as_float), p[axis]);
    }
  }
}

}  // namespace
