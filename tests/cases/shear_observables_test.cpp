// The shear observables against shapes whose answers are known: an ellipsoid (length, breadth,
// deformation index, inclination), a point turning at a known frequency, dihedral changes.
#include "cases/shear_observables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mesh/icosphere.hpp"

namespace rbcsim::cases {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The level-4 icosphere stretched to semi-axes (a, b, c) along x, y, z, turned by angle_rad about
// z and moved to `centre`. The icosphere's vertices have isotropic second moments (icosahedral
// symmetry), so the ellipsoid's principal axes are exactly the turned x, y, z.
std::vector<Vec3> ellipsoid(double a, double b, double c, double angle_rad, const Vec3& centre) {
  std::vector<Vec3> positions;
  const double cosine = std::cos(angle_rad), sine = std::sin(angle_rad);
  for (const Vec3& p : mesh::unit_icosphere(4).positions_um) {
    const Vec3 s(a * p.x(), b * p.y(), c * p.z());
    positions.push_back(centre +
                        Vec3(cosine * s.x() - sine * s.y(), sine * s.x() + cosine * s.y(), s.z()));
  }
  return positions;
}

TEST(ShearObservables, EllipsoidInTheShearPlane) {
  const double a = 5.0, b = 2.0, c = 1.2;
  for (const double angle_deg : {0.0, 30.0, -20.0, 75.0}) {
    const auto shape = measure_shear_shape(ellipsoid(a, b, c, angle_deg * kDegree, {3, -1, 2}));
    // The vertices sample the surface: on level 4 (2562 vertices, ~4 degrees apart) the
    // largest distances fall short of the axes by at most 1 - cos(2 degrees) ~ 0.1 %.
    EXPECT_NEAR(shape.length_um, 2.0 * a, 2.0 * a * 2e-3) << angle_deg;
    EXPECT_NEAR(shape.breadth_um, 2.0 * b, 2.0 * b * 2e-3) << angle_deg;
    EXPECT_NEAR(shape.deformation_index, (a - b) / (a + b), 2e-3) << angle_deg;
    EXPECT_NEAR(shape.inclination_deg, angle_deg, 1e-9) << angle_deg;
  }
}

TEST(ShearObservables, InclinationIsInTheHalfOpenRightHalfPlane) {
  EXPECT_NEAR(in_plane_major_axis_rad(ellipsoid(5, 2, 1, 90.0 * kDegree, Vec3::Zero())),
              0.5 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(in_plane_major_axis_rad(ellipsoid(5, 2, 1, 120.0 * kDegree, Vec3::Zero())),
              -60.0 * kDegree, 1e-9);
}

TEST(ShearObservables, SphereHasNoDeformation) {
  const auto shape = measure_shear_shape(ellipsoid(3, 3, 3, 0.0, Vec3::Zero()));
  EXPECT_NEAR(shape.length_um, 6.0, 6.0 * 2e-3);
  EXPECT_NEAR(shape.deformation_index, 0.0, 2e-3);
}

TEST(ShearObservables, LargestDistanceOfAFewPoints) {
  const std::vector<Vec3> points{{0, 0, 0}, {1, 2, 2}, {-1, 0, 0}, {0.5, 0.5, 0.5}};
  EXPECT_DOUBLE_EQ(largest_vertex_distance_um(points), std::sqrt(4.0 + 4.0 + 4.0));
}

// A point on a circle about (1, 2) in the x-y plane turning clockwise (the vorticity's sense in
// shear along +x growing with y) at 3.5 Hz, sampled 20 times per turn for 4 turns.
TEST(ShearObservables, FrequencyOfATrackedPoint) {
  const double frequency_hz = 3.5;
  const Vec3 centre(1.0, 2.0, 0.4);
  std::vector<double> times_s, angles_rad;
  for (int sample = 0; sample <= 80; ++sample) {
    const double t = sample / (20.0 * frequency_hz);
    const double phase = -2.0 * std::numbers::pi * frequency_hz * t + 0.3;
    const Vec3 point = centre + 1.7 * Vec3(std::cos(phase), std::sin(phase), 0.1);
    const double angle = in_plane_angle_rad(point, centre);
    angles_rad.push_back(angles_rad.empty() ? angle : unwrap_angle_rad(angles_rad.back(), angle));
    times_s.push_back(t);
  }
  EXPECT_NEAR(angles_rad.back() - angles_rad.front(), -8.0 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(rotation_frequency_hz(times_s, angles_rad), frequency_hz, 1e-9);
  for (double& angle : angles_rad) angle = -angle;  // counter-clockwise: negative
  EXPECT_NEAR(rotation_frequency_hz(times_s, angles_rad), -frequency_hz, 1e-9);
}

TEST(ShearObservables, UnwrapKeepsTheAngleContinuous) {
  EXPECT_NEAR(unwrap_angle_rad(3.0, -3.0), 2.0 * std::numbers::pi - 3.0, 1e-12);
  EXPECT_NEAR(unwrap_angle_rad(-9.0, 3.0), 3.0 - 4.0 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(unwrap_angle_rad(0.1, 0.2), 0.2, 1e-12);
}

TEST(ShearObservables, DihedralChangeRms) {
  const std::vector<double> angles{0.1, -0.1, 0.5};
  const std::vector<double> reference{0.0, 0.0, 0.2};
  EXPECT_DOUBLE_EQ(dihedral_change_rms_rad(angles, reference), std::sqrt(0.11 / 3.0));
  EXPECT_EQ(dihedral_change_rms_rad(reference, reference), 0.0);
  EXPECT_THROW(dihedral_change_rms_rad(angles, std::vector<double>{0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace rbcsim::cases
