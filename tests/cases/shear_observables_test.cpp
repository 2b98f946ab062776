// The shear observables against shapes whose answers are known: an ellipsoid (length, breadth,
// deformation index, inclination), a point turning at a known frequency, dihedral changes, and the
// roughness against a rigid motion, a smooth stretch and imposed wrinkles of a sphere.
#include "cases/shear_observables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mesh/geometry.hpp"
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

// A point turning clockwise by pi/8 per sample: the last half turn holds 8 samples (the ninth
// back is pi away, exactly: pi/8 and its multiples up to pi are exact in binary).
TEST(ShearObservables, LastHalfTurnCountsTheSamplesWithinPiOfTheFinalAngle) {
  std::vector<double> angles_rad;
  for (int k = 0; k < 20; ++k) angles_rad.push_back(-k * std::numbers::pi / 8.0);
  EXPECT_EQ(samples_in_last_half_turn(angles_rad), 8u);
  EXPECT_EQ(samples_in_last_half_turn(std::span(angles_rad).first(8)), 0u);  // 7 pi / 8 only
  EXPECT_EQ(samples_in_last_half_turn(std::span(angles_rad).first(9)), 8u);
  EXPECT_EQ(samples_in_last_half_turn({}), 0u);
}

// A swinging cell: length 8 + 0.5 sin(2 theta), the tracked point turning as above. The mean over
// the last half turn (one period of the swing) is the oscillation's mean; over five samples, not a
// whole period, it is off by more than a tenth of the amplitude.
TEST(ShearObservables, MeanOverTheLastHalfTurnIsTheSwingsMean) {
  std::vector<double> angles_rad;
  std::vector<ShearShape> shapes;
  for (int k = 0; k < 30; ++k) {
    const double angle = -k * std::numbers::pi / 8.0;
    angles_rad.push_back(angle);
    const double length = 8.0 + 0.5 * std::sin(2.0 * angle);
    const double breadth = 3.0 - 0.2 * std::sin(2.0 * angle);
    shapes.push_back({length, breadth, (length - breadth) / (length + breadth),
                      20.0 + 5.0 * std::cos(2.0 * angle)});
  }
  const auto window = samples_in_last_half_turn(angles_rad);
  const auto averaged = average_shapes(std::span(shapes).last(window));
  EXPECT_NEAR(averaged.mean.length_um, 8.0, 1e-12);
  EXPECT_NEAR(averaged.mean.breadth_um, 3.0, 1e-12);
  EXPECT_NEAR(averaged.mean.inclination_deg, 20.0, 1e-12);
  EXPECT_NEAR(averaged.length_swing_um, 1.0, 1e-12);  // sin(2 theta) reaches +-1 on these phases
  EXPECT_GT(std::abs(average_shapes(std::span(shapes).last(5)).mean.length_um - 8.0), 0.05);
  EXPECT_THROW(average_shapes({}), std::invalid_argument);
}

TEST(ShearObservables, DihedralChangeRms) {
  const std::vector<double> angles{0.1, -0.1, 0.5};
  const std::vector<double> reference{0.0, 0.0, 0.2};
  EXPECT_DOUBLE_EQ(dihedral_change_rms_rad(angles, reference), std::sqrt(0.11 / 3.0));
  EXPECT_EQ(dihedral_change_rms_rad(reference, reference), 0.0);
  EXPECT_THROW(dihedral_change_rms_rad(angles, std::vector<double>{0.0}), std::invalid_argument);
}

// The roughness fixtures: the level-4 unit icosphere (2562 vertices, mean edge h ~ 0.0755) as the
// stress-free reference and the dihedral angles of deformed copies of it.
struct RoughnessFixture {
  mesh::TriangleMesh sphere = mesh::unit_icosphere(4);
  mesh::MeshTopology topology = mesh::MeshTopology::build(sphere);
  std::vector<double> reference_rad = angles_of(sphere.positions_um);

  std::vector<double> angles_of(std::span<const Vec3> positions_um) const {
    std::vector<double> angles;
    for (const mesh::Edge& edge : topology.edges()) {
      angles.push_back(mesh::signed_dihedral_angle_rad(positions_um, edge));
    }
    return angles;
  }
  double old_rms_rad(std::span<const Vec3> positions_um) const {
    return dihedral_change_rms_rad(angles_of(positions_um), reference_rad);
  }
  double roughness_rad(std::span<const Vec3> positions_um) const {
    return dihedral_roughness_rad(angles_of(positions_um), reference_rad, topology);
  }
  double mean_edge_length() const {
    double sum = 0.0;
    for (const mesh::Edge& edge : topology.edges()) {
      sum += mesh::edge_length_um(sphere.positions_um, edge);
    }
    return sum / static_cast<double>(topology.edge_count());
  }
  // The sphere with the radial wrinkle r = 1 + amplitude sin(2 pi x / wavelength).
  std::vector<Vec3> wrinkled(double amplitude, double wavelength) const {
    std::vector<Vec3> positions;
    for (const Vec3& p : sphere.positions_um) {
      positions.push_back(
          p * (1.0 + amplitude * std::sin(2.0 * std::numbers::pi * p.x() / wavelength)));
    }
    return positions;
  }
};

TEST(ShearObservables, RoughnessIsZeroForARigidMotion) {
  const RoughnessFixture fixture;
  std::vector<Vec3> moved;
  for (const Vec3& p : fixture.sphere.positions_um) {
    moved.push_back(Vec3(0.6 * p.x() - 0.8 * p.y(), 0.8 * p.x() + 0.6 * p.y(), p.z()) +
                    Vec3(2.0, -1.0, 0.5));
  }
  // Only the rounding of the angles' acos/atan2 (~1e-8 near theta ~ 0.08) is left.
  EXPECT_LT(fixture.roughness_rad(moved), 1e-7);
  EXPECT_LT(fixture.old_rms_rad(moved), 1e-7);
}

// The affine stretch 1.3 x 0.8 x 1.0 is smooth on the cell's scale R = 1: its dihedral changes
// are ~ 0.01 rad (the old RMS, clearly non-zero). Bound on the roughness: (i) the umbrella
// Laplacian leaves (h / R)^2 / 4 ~ 1.4e-3 of a change smooth on the scale R; (ii) the star mean
// is direction-free only for equally spaced edge directions; the icosphere's star angles differ
// from 2 pi / n by up to ~10 % (largest near the 12 five-valent vertices), which leaves about that
// fraction of the anisotropic change, i.e. at most ~5 % as an RMS. Bound: 5 % of the old RMS.
TEST(ShearObservables, RoughnessIgnoresASmoothStretch) {
  const RoughnessFixture fixture;
  std::vector<Vec3> stretched;
  for (const Vec3& p : fixture.sphere.positions_um) {
    stretched.push_back(Vec3(1.3 * p.x(), 0.8 * p.y(), p.z()));
  }
  const double old_rms = fixture.old_rms_rad(stretched);
  EXPECT_GT(old_rms, 0.005);
  EXPECT_LT(fixture.roughness_rad(stretched), 0.05 * old_rms);
}

// A wrinkle of wavelength 4 h keeps a large part of its dihedral change through the filter:
// the star mean halves a curvature along one direction and keeps J0(k h / 2) ~ 0.85 of it, the
// umbrella Laplacian keeps 1 - J0(k h) ~ 0.5 (k h = pi / 2): about a fifth overall. So the
// roughness is at least a tenth of the old RMS, at least 20 times the stretch's bound above, and
// linear in the (small) amplitude.
TEST(ShearObservables, RoughnessSeesAWrinkle) {
  const RoughnessFixture fixture;
  const double wavelength = 4.0 * fixture.mean_edge_length();
  const auto small = fixture.wrinkled(0.01, wavelength);
  const auto large = fixture.wrinkled(0.02, wavelength);
  const double small_roughness = fixture.roughness_rad(small);
  EXPECT_GT(small_roughness, 0.1 * fixture.old_rms_rad(small));
  const double stretch_bound_rad = 0.05 * 0.01;  // 5 % of the stretch's old RMS (< 0.01)
  EXPECT_GT(small_roughness, 20.0 * stretch_bound_rad);
  EXPECT_NEAR(fixture.roughness_rad(large) / small_roughness, 2.0, 0.2);
}

TEST(ShearObservables, RoughnessNeedsOneAnglePerEdge) {
  const RoughnessFixture fixture;
  EXPECT_THROW(
      dihedral_roughness_rad(fixture.reference_rad, std::vector<double>{0.0}, fixture.topology),
      std::invalid_argument);
}

}  // namespace
}  // namespace rbcsim::cases
