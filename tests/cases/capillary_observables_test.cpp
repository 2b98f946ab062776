// The capillary observables on shapes whose answers are known by hand: the extents and the
// deformation index (paper Eq. 19) of an octahedron with given half-axes, the transit of a
// centroid moving at constant speed, and the dimensionless numbers of the paper's flows.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "cases/capillary_observables.hpp"

namespace rbcsim::cases {
namespace {

// The six vertices (+-a, 0, 0), (0, +-b, 0), (0, 0, +-c) shifted by `centre`.
std::vector<Vec3> octahedron(double a, double b, double c, const Vec3& centre) {
  return {centre + Vec3(a, 0, 0),  centre + Vec3(-a, 0, 0), centre + Vec3(0, b, 0),
          centre + Vec3(0, -b, 0), centre + Vec3(0, 0, c),  centre + Vec3(0, 0, -c)};
}

TEST(CapillaryObservables, CentroidExtentsAndDeformationIndexOfAnOctahedron) {
  const Vec3 centre(12.0, -0.5, 0.25);
  const auto points = octahedron(4.5, 3.0, 1.25, centre);
  EXPECT_LT((vertex_centroid(points) - centre).norm(), 1e-14);
  EXPECT_LT((vertex_extents(points) - Vec3(9.0, 6.0, 2.5)).norm(), 1e-14);
  EXPECT_DOUBLE_EQ(deformation_index(points), 1.5);
  // A disc in the x-y plane (the release orientation): DI = 1 whatever its thickness.
  EXPECT_DOUBLE_EQ(deformation_index(octahedron(3.9, 3.9, 1.3, centre)), 1.0);
  EXPECT_THROW(deformation_index(octahedron(1.0, 0.0, 1.0, centre)), std::invalid_argument);
}

TEST(CapillaryObservables, MeanVelocityIsTheCentroidVelocity) {
  const std::vector<Vec3> velocities{{1.0, 0.0, 0.0}, {3.0, 2.0, -1.0}};
  EXPECT_LT((mean_velocity(velocities) - Vec3(2.0, 1.0, -0.5)).norm(), 1e-15);
}

// x(t) = x0 + v t sampled every dt: the interpolated crossings are exact for a linear motion,
// even when no sample falls on them.
TEST(CapillaryObservables, TransitOfAUniformMotionIsLengthOverSpeed) {
  const double x0_um = 2.0;
  const double speed_um_per_s = 5000.0;
  NarrowSectionTransit transit(10.4, 20.8);
  const double dt_s = 3.7e-5;
  for (int step = 0; step < 200; ++step) {
    const double time_s = step * dt_s;
    transit.add_sample(time_s, x0_um + speed_um_per_s * time_s);
  }
  ASSERT_TRUE(transit.passed());
  EXPECT_NEAR(*transit.entry_time_s(), (10.4 - x0_um) / speed_um_per_s, 1e-15);
  EXPECT_NEAR(*transit.exit_time_s(), (20.8 - x0_um) / speed_um_per_s, 1e-15);
  EXPECT_NEAR(*transit.transit_time_s(), 10.4 / speed_um_per_s, 1e-15);
}

TEST(CapillaryObservables, ACellThatStopsInTheThroatHasEnteredButNotPassed) {
  NarrowSectionTransit transit(10.0, 20.0);
  for (const double x_um : {5.0, 9.0, 11.0, 15.0, 14.0, 15.0}) transit.add_sample(x_um, x_um);
  EXPECT_NEAR(*transit.entry_time_s(), 10.0, 1e-15);
  EXPECT_FALSE(transit.passed());
  EXPECT_FALSE(transit.transit_time_s());
  EXPECT_THROW(NarrowSectionTransit(5.0, 5.0), std::invalid_argument);
}

// docs/physics.md, "Capillary": with plasma (1.1e-6 m^2/s), 0.04 m/s in a 10.2 um tube is
// Re = 0.37, and the paper's Re = 0.0643 would need nu ~ 6.3e-6 m^2/s.
TEST(CapillaryObservables, TheReynoldsNumbersOfThePaperFlows) {
  EXPECT_NEAR(reynolds_number(0.04, 10.2, 1.1e-6), 0.04 * 10.2e-6 / 1.1e-6, 1e-12);
  EXPECT_NEAR(reynolds_number(0.04, 10.2, 1.1e-6), 0.371, 1e-3);
  EXPECT_NEAR(reynolds_number(0.04, 10.2, 6.345e-6), 0.0643, 1e-4);
}

// Eq. 6 at d = 0: dF/dL = k kBT (1 + 1/tau^2) / (p L0); Table 2's k_l = 7, tau_l = 3, p = 7.5 nm,
// L0 = 0.25 um give 7 * 4.1005e-21 J * 10/9 / (1.875e-15 m^2) = 1.7009e-5 N/m, and the harmonic
// triangular network mu = sqrt(3)/4 of it: 7.365 uN/m. Ca = mu_plasma U / mu.
TEST(CapillaryObservables, LinkShearModulusAndCapillaryNumber) {
  const double modulus = link_shear_modulus_N_per_m(7.0, 3.0, 4.100531391e-21, 0.0075, 0.25);
  EXPECT_NEAR(modulus * 1e6, 7.365, 1e-3);
  // Longer edges, softer links: mu ~ 1/L0, so a coarser mesh of the same cell is softer.
  EXPECT_NEAR(link_shear_modulus_N_per_m(7.0, 3.0, 4.100531391e-21, 0.0075, 0.5), 0.5 * modulus,
              1e-18);
  EXPECT_NEAR(capillary_number(0.01, 1.1275e-3, modulus), 1.1275e-5 / modulus, 1e-12);
}

}  // namespace
}  // namespace rbcsim::cases
