// The stretch frame and the two diameters, on shapes whose answers are known in closed form.
#include "cases/stretch_geometry.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "mesh/icosphere.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::Vec3;
namespace cases = rbcsim::cases;

rbcsim::mesh::TriangleMesh ellipsoid(const Vec3& semi_axes_um) {
  auto mesh = rbcsim::mesh::unit_icosphere(3);
  for (auto& p : mesh.positions_um) p = p.cwiseProduct(semi_axes_um);
  return mesh;
}

// The icosphere has vertices on its three axes, so the extents are exactly twice the semi-axes.
TEST(StretchGeometry, DiametersOfAnEllipsoid) {
  const auto mesh = ellipsoid(Vec3(4.0, 3.0, 1.5));
  EXPECT_NEAR(cases::axial_diameter_um(mesh.positions_um), 8.0, 1e-12);
  EXPECT_NEAR(cases::transverse_diameter_um(mesh.positions_um), 6.0, 1e-12);
  // Thicker than wide (a cell that rounded up): the image still shows the width along y.
  const auto tall = ellipsoid(Vec3(4.0, 1.5, 3.0));
  EXPECT_NEAR(cases::transverse_diameter_um(tall.positions_um), 3.0, 1e-12);
}

// The transverse diameter is the width of the image (the projection along z) across the pull:
// for a square cross-section of side 2 it is the side, not the diagonal of the y-z projection.
TEST(StretchGeometry, TransverseDiameterIsTheImageWidth) {
  const std::vector<Vec3> corners{Vec3(0, 1, 1),   Vec3(5, -1, 1), Vec3(-3, 1, -1),
                                  Vec3(1, -1, -1), Vec3(0, 0, 0),  Vec3(2, 0.5, -0.2)};
  EXPECT_NEAR(cases::transverse_diameter_um(corners), 2.0, 1e-12);
  EXPECT_NEAR(cases::axial_diameter_um(corners), 8.0, 1e-12);
}

// A disc lying with its thin axis on y is turned so that it lies in the image plane x-y (z, the
// line of sight, its thinnest axis): the transverse diameter is then its width, not its thickness.
TEST(StretchGeometry, FrameTurnsTheThinAxisOntoTheLineOfSight) {
  const auto disc = ellipsoid(Vec3(4.0, 1.5, 3.9));
  const auto framed = cases::in_stretch_frame(disc);
  EXPECT_NEAR(cases::axial_diameter_um(framed.positions_um), 8.0, 1e-9);
  EXPECT_NEAR(cases::transverse_diameter_um(framed.positions_um), 7.8, 1e-9);
}

// A cell with a long axis elsewhere is turned onto x and centred; a cell whose x is already a
// longest axis (the built-in discocyte) is only centred.
TEST(StretchGeometry, FrameTurnsTheLongAxisOntoX) {
  auto mesh = ellipsoid(Vec3(1.5, 4.0, 3.0));
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (auto& p : mesh.positions_um) p = rotation * p + Vec3(5, -2, 1);
  const auto framed = cases::in_stretch_frame(mesh);
  EXPECT_NEAR(cases::axial_diameter_um(framed.positions_um), 8.0, 1e-9);

  const auto discocyte = cases::testing::evans_fung_discocyte(3);
  const auto kept = cases::in_stretch_frame(discocyte);
  const Vec3 shift = kept.positions_um[0] - discocyte.positions_um[0];
  for (std::size_t i = 0; i < kept.vertex_count(); ++i) {
    EXPECT_NEAR((kept.positions_um[i] - discocyte.positions_um[i] - shift).norm(), 0.0, 1e-12);
  }
  EXPECT_NEAR(cases::axial_diameter_um(kept.positions_um), 7.82, 1e-6);
  EXPECT_NEAR(cases::transverse_diameter_um(kept.positions_um), 7.82, 1e-6);
}

}  // namespace
