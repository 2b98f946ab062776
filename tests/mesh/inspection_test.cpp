// MeshReport on solids whose answers are known: counts, topology flags, genus from the Euler
// characteristic, size, principal extents, quality and the curvature reference sums.
#include "mesh/inspection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/icosphere.hpp"
#include "mesh_test_support.hpp"

namespace {

using rbcsim::Vec3;
using namespace rbcsim::mesh;
using rbcsim::mesh::testing::octahedron;

TEST(Inspection, OctahedronIsAClosedGenusZeroSolidOfKnownSize) {
  const auto report = inspect_mesh(octahedron());
  EXPECT_EQ(report.vertex_count, 6u);
  EXPECT_EQ(report.edge_count, 12u);
  EXPECT_EQ(report.triangle_count, 8u);
  EXPECT_EQ(report.component_count, 1u);
  EXPECT_TRUE(report.closed && report.manifold && report.oriented);
  EXPECT_EQ(report.euler_characteristic, 2);
  EXPECT_EQ(report.genus, 0);
  EXPECT_NEAR(report.area_um2, 4.0 * std::sqrt(3.0), 1e-12);  // 8 triangles of side sqrt 2
  EXPECT_NEAR(report.volume_um3, 4.0 / 3.0, 1e-12);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(report.principal_extents_um[k], 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(report.bounding_box_min_um[k], -1.0);
    EXPECT_DOUBLE_EQ(report.bounding_box_max_um[k], 1.0);
  }
  EXPECT_NEAR(report.edge_min_um, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(report.edge_max_um, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(report.edge_stddev_um, 0.0, 1e-7);
  EXPECT_NEAR(report.min_angle_deg, 60.0, 1e-9);
  EXPECT_NEAR(report.max_angle_deg, 60.0, 1e-9);
  EXPECT_EQ(report.degenerate_triangle_count, 0u);
  EXPECT_EQ(report.sliver_triangle_count, 0u);
  ASSERT_TRUE(report.curvature.has_value());
  // 12 edges of length sqrt 2 with exterior dihedral angle arccos(1/3), all convex.
  EXPECT_NEAR(report.curvature->signed_um, 6.0 * std::sqrt(2.0) * std::acos(1.0 / 3.0), 1e-12);
  EXPECT_NEAR(report.curvature->absolute_um, report.curvature->signed_um, 1e-12);
}

TEST(Inspection, PrincipalExtentsOfAnEllipsoidComeLargestFirst) {
  auto ellipsoid = unit_icosphere(4);
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (auto& p : ellipsoid.positions_um) {
    const Vec3 stretched(1.0 * p.x(), 3.0 * p.y(), 2.0 * p.z());
    p = Vec3(c * stretched.x() - s * stretched.y(), s * stretched.x() + c * stretched.y(),
             stretched.z());
  }
  const auto report = inspect_mesh(ellipsoid);
  // Level-4 vertices reach the ends of the axes to within the chord error (~0.5 %).
  EXPECT_NEAR(report.principal_extents_um[0], 6.0, 0.03);
  EXPECT_NEAR(report.principal_extents_um[1], 4.0, 0.03);
  EXPECT_NEAR(report.principal_extents_um[2], 2.0, 0.03);
}

TEST(Inspection, TwoSpheresAndAnOpenSurface) {
  auto two = octahedron();
  for (const auto& p : octahedron().positions_um) two.positions_um.push_back(p + Vec3(3, 0, 0));
  for (auto t : octahedron().triangles) two.triangles.push_back({t[0] + 6, t[1] + 6, t[2] + 6});
  const auto pair = inspect_mesh(two);
  EXPECT_EQ(pair.component_count, 2u);
  EXPECT_EQ(pair.euler_characteristic, 4);
  EXPECT_EQ(pair.genus, 0);  // (2 C - chi) / 2 = (4 - 4) / 2

  auto open = octahedron();
  open.triangles.pop_back();
  const auto holed = inspect_mesh(open);
  EXPECT_FALSE(holed.closed);
  EXPECT_FALSE(holed.oriented);
  EXPECT_EQ(holed.boundary_edge_count, 3u);
  EXPECT_FALSE(holed.genus.has_value());
  EXPECT_FALSE(holed.curvature.has_value());
}

TEST(Inspection, CountsSliversAndDegenerateTriangles) {
  auto mesh = octahedron();
  // The top vertex far up: its four triangles become needles with an apex angle of
  // 2 atan((sqrt 2 / 2) / sqrt(20^2 + 1/2)) = 4 deg.
  mesh.positions_um[4] = Vec3(0, 0, 20);
  auto report = inspect_mesh(mesh);
  EXPECT_EQ(report.sliver_triangle_count, 4u);
  EXPECT_NEAR(report.min_angle_deg,
              2.0 * std::atan(std::sqrt(0.5) / std::sqrt(400.0 + 0.5)) * 180.0 / std::numbers::pi,
              1e-9);
  // The top vertex on the midpoint of edge (0, 2): triangle (0, 2, 4) has zero area.
  mesh.positions_um[4] = Vec3(0.5, 0.5, 0);
  report = inspect_mesh(mesh);
  EXPECT_EQ(report.degenerate_triangle_count, 1u);
}

TEST(Inspection, JsonAndTextCarryTheNumbers) {
  const auto report = inspect_mesh(octahedron());
  const auto json = to_json(report);
  EXPECT_EQ(json["counts"]["vertices"], 6);
  EXPECT_EQ(json["topology"]["genus"], 0);
  EXPECT_DOUBLE_EQ(json["size"]["volume_um3"].get<double>(), report.volume_um3);
  EXPECT_DOUBLE_EQ(json["reference_sums"]["total_curvature_C0_over_2D0_um"].get<double>(),
                   report.curvature->absolute_um);
  EXPECT_EQ(json["size"]["principal_extents_um"].size(), 3u);
  const auto text = to_text(report);
  EXPECT_NE(text.find("genus                           0"), std::string::npos) << text;
  EXPECT_NE(text.find("DeltaA0/(2 D0)"), std::string::npos);
}

}  // namespace
