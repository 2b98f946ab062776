#include "geometry/capillary_wall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.hpp"

namespace {

using rbcsim::geometry::CapillaryParameters;
using rbcsim::geometry::CapillaryWall;

CapillaryParameters symmetric_capillary(const std::string& profile) {
  CapillaryParameters p;
  p.length_um = 30.0;
  p.inlet_diameter_um = 10.0;
  p.outlet_diameter_um = 10.0;
  p.throat_diameter_um = 6.0;
  p.constriction_length_um = 12.0;
  p.constriction_centre_um = 13.0;  // off the tube's centre on purpose
  p.profile = profile;
  return p;
}

TEST(CapillaryWall, PaperValidationPresetRadii) {
  const CapillaryWall wall(rbcsim::geometry::paper_validation_capillary());
  EXPECT_DOUBLE_EQ(wall.length_um(), 31.2);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(0.0), 5.1);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(15.6), 3.375);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(31.2), 5.1);
  // Documented defaults: a constriction a third of the length long, centred.
  EXPECT_DOUBLE_EQ(*wall.parameters().constriction_length_um, 31.2 / 3.0);
  EXPECT_DOUBLE_EQ(*wall.parameters().constriction_centre_um, 15.6);
  EXPECT_EQ(wall.parameters().profile, "cosine");
}

TEST(CapillaryWall, PaperMorphologyPresetRadii) {
  const CapillaryWall wall(rbcsim::geometry::paper_morphology_capillary());
  EXPECT_DOUBLE_EQ(wall.length_um(), 42.0);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(0.0), 5.0);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(21.0), 3.4);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(42.0), 5.0);
  EXPECT_DOUBLE_EQ(wall.constriction_start_um(), 14.0);
  EXPECT_DOUBLE_EQ(wall.constriction_end_um(), 28.0);
}

TEST(CapillaryWall, StraightOutsideTheConstriction) {
  const CapillaryWall wall(symmetric_capillary("cosine"));
  for (double x_um : {-3.0, 0.0, 6.9, 7.0, 19.0, 25.0, 30.0, 33.0}) {
    EXPECT_DOUBLE_EQ(*wall.radius_at_um(x_um), 5.0) << "x = " << x_um;
  }
}

class BothProfiles : public ::testing::TestWithParam<std::string> {};

TEST_P(BothProfiles, ConstrictionIsSymmetricAboutItsCentre) {
  const CapillaryWall wall(symmetric_capillary(GetParam()));
  for (double offset_um = 0.0; offset_um <= 13.0; offset_um += 0.37) {
    EXPECT_NEAR(*wall.radius_at_um(13.0 - offset_um), *wall.radius_at_um(13.0 + offset_um), 1e-12)
        << "offset " << offset_um;
  }
}

TEST_P(BothProfiles, MonotonicFromInletToThroatAndBackToOutlet) {
  const CapillaryWall wall(symmetric_capillary(GetParam()));
  for (double x_um = 0.0; x_um < 30.0; x_um += 0.1) {
    const double here = *wall.radius_at_um(x_um);
    const double next = *wall.radius_at_um(x_um + 0.1);
    if (x_um + 0.1 <= 13.0) {
      EXPECT_LE(next, here + 1e-15) << "x = " << x_um;
    }
    if (x_um >= 13.0) {
      EXPECT_GE(next, here - 1e-15) << "x = " << x_um;
    }
  }
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(13.0), 3.0);
}

INSTANTIATE_TEST_SUITE_P(Profiles, BothProfiles, ::testing::Values("cosine", "linear"));

TEST(CapillaryWall, CosineProfileMatchesTheFormula) {
  const CapillaryWall wall(symmetric_capillary("cosine"));
  for (double x_um = 7.0; x_um <= 19.0; x_um += 0.25) {
    // D(x) = D_in - (D_in - D_throat) (1 + cos(2 pi (x - x_c) / L_c)) / 2
    const double diameter_um =
        10.0 - 4.0 * (1.0 + std::cos(2.0 * std::numbers::pi * (x_um - 13.0) / 12.0)) / 2.0;
    EXPECT_NEAR(*wall.radius_at_um(x_um), diameter_um / 2.0, 1e-12) << "x = " << x_um;
  }
}

// One-sided slopes (r(x + h) - r(x)) / h at the two ends of the constriction, from inside.
struct EndSlopes {
  double at_start;
  double at_end;
};
EndSlopes inner_slopes_at_ends(const CapillaryWall& wall, double h_um) {
  const double start = wall.constriction_start_um();
  const double end = wall.constriction_end_um();
  return {(*wall.radius_at_um(start + h_um) - *wall.radius_at_um(start)) / h_um,
          (*wall.radius_at_um(end) - *wall.radius_at_um(end - h_um)) / h_um};
}

TEST(CapillaryWall, CosineProfileIsSmoothAtTheConstrictionEnds) {
  const CapillaryWall wall(symmetric_capillary("cosine"));
  // Outside the slope is 0. Inside, R_in - r(x_start + h) = (dD / 4)(1 - cos(pi delta)) with
  // delta = 2 h / L_c, at most dD pi^2 h^2 / (2 L_c^2): the inner slope vanishes like h, so the
  // radius is C1 at the ends (dD = 4 um, L_c = 12 um).
  for (double h_um : {1e-1, 1e-2, 1e-3}) {
    const double slope_bound = 4.0 * std::numbers::pi * std::numbers::pi * h_um / (2.0 * 144.0);
    const auto slopes = inner_slopes_at_ends(wall, h_um);
    EXPECT_LE(std::abs(slopes.at_start), slope_bound) << "h = " << h_um;
    EXPECT_LE(std::abs(slopes.at_end), slope_bound) << "h = " << h_um;
    EXPECT_LT(slopes.at_start, 0.0);  // narrowing, however gently
    EXPECT_GT(slopes.at_end, 0.0);
  }
}

TEST(CapillaryWall, LinearProfileHasKinksAndTheExpectedValues) {
  const CapillaryWall wall(symmetric_capillary("linear"));
  // Radius falls linearly from 5 at x = 7 to 3 at x = 13, then rises to 5 at x = 19.
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(7.0), 5.0);
  EXPECT_NEAR(*wall.radius_at_um(8.5), 4.5, 1e-12);
  EXPECT_NEAR(*wall.radius_at_um(10.0), 4.0, 1e-12);
  EXPECT_NEAR(*wall.radius_at_um(13.0), 3.0, 1e-12);
  EXPECT_NEAR(*wall.radius_at_um(17.5), 4.5, 1e-12);
  // The smoothness check of the cosine profile must fail here: the slope is -1/3 at the ends.
  const auto slopes = inner_slopes_at_ends(wall, 1e-3);
  EXPECT_NEAR(slopes.at_start, -1.0 / 3.0, 1e-9);
  EXPECT_NEAR(slopes.at_end, 1.0 / 3.0, 1e-9);
}

TEST(CapillaryWall, DifferentInletAndOutletDiameters) {
  CapillaryParameters p = symmetric_capillary("cosine");
  p.outlet_diameter_um = 8.0;
  const CapillaryWall wall(p);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(0.0), 5.0);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(30.0), 4.0);
  EXPECT_DOUBLE_EQ(*wall.radius_at_um(13.0), 3.0);
  EXPECT_NEAR(*wall.radius_at_um(10.0), (10.0 + 6.0) / 4.0, 1e-12);  // halfway in
  EXPECT_NEAR(*wall.radius_at_um(16.0), (8.0 + 6.0) / 4.0, 1e-12);   // halfway out
  EXPECT_DOUBLE_EQ(wall.largest_radius_um(), 5.0);
}

TEST(CapillaryWall, FluidInsideTheLumenOnly) {
  const CapillaryWall wall(symmetric_capillary("cosine"));
  EXPECT_TRUE(wall.is_fluid({13.0, 2.9, 0.0}));
  EXPECT_FALSE(wall.is_fluid({13.0, 0.0, 3.1}));
  EXPECT_TRUE(wall.is_fluid({1.0, 3.0, 3.0}));   // r = 4.24 < 5
  EXPECT_FALSE(wall.is_fluid({1.0, 3.6, 3.6}));  // r = 5.09 > 5
  const auto bounds = wall.fluid_bounds();
  EXPECT_EQ(bounds.min_um, rbcsim::Vec3(0.0, -5.0, -5.0));
  EXPECT_EQ(bounds.max_um, rbcsim::Vec3(30.0, 5.0, 5.0));
  EXPECT_TRUE(bounds.open_axes[0]);
  EXPECT_FALSE(bounds.open_axes[1] || bounds.open_axes[2]);
}

// The message names the offending parameter with the source prefix.
void expect_rejected(const CapillaryParameters& p, const std::string& parameter) {
  try {
    CapillaryWall wall(p, "capillary.wall");
    FAIL() << "accepted; expected an error naming " << parameter;
  } catch (const rbcsim::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("capillary.wall." + parameter + ":"),
              std::string::npos)
        << error.what();
  }
}

TEST(CapillaryWall, RejectsDegenerateParameters) {
  const auto base = symmetric_capillary("cosine");
  auto p = base;
  p.throat_diameter_um = 10.0;
  expect_rejected(p, "throat_diameter_um");
  p = base;
  p.throat_diameter_um = 11.0;
  expect_rejected(p, "throat_diameter_um");
  p = base;
  p.outlet_diameter_um = 5.0;  // throat 6 wider than the outlet
  expect_rejected(p, "throat_diameter_um");
  p = base;
  p.length_um = -30.0;
  expect_rejected(p, "length_um");
  p = base;
  p.inlet_diameter_um = 0.0;
  expect_rejected(p, "inlet_diameter_um");
  p = base;
  p.throat_diameter_um = std::nan("");
  expect_rejected(p, "throat_diameter_um");
  p = base;
  p.constriction_length_um = -1.0;
  expect_rejected(p, "constriction_length_um");
  p = base;
  p.constriction_length_um = 31.0;
  expect_rejected(p, "constriction_length_um");
  p = base;
  p.constriction_length_um = 28.0;  // [-1, 27] around x_c = 13 sticks out of [0, 30]
  expect_rejected(p, "constriction_centre_um");
  p = base;
  p.constriction_centre_um = 25.0;  // [19, 31]
  expect_rejected(p, "constriction_centre_um");
  p = base;
  p.profile = "gaussian";
  expect_rejected(p, "profile");
}

}  // namespace
