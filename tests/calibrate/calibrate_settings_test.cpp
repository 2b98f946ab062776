// calibrate.* options -> CalibrationSettings: the defaults are the struct's, and every option
// reaches its field.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "config/config.hpp"
#include "setup/calibrate_from_config.hpp"

namespace {

using rbcsim::config::resolve_config;

TEST(CalibrateSettings, DefaultsAreTheCasesOwn) {
  const auto settings = rbcsim::setup::calibration_settings_from(resolve_config());
  const rbcsim::cases::CalibrationSettings defaults;
  EXPECT_EQ(settings.fits, defaults.fits);
  EXPECT_EQ(settings.patch_edge, defaults.patch_edge);
  EXPECT_EQ(settings.targets.moduli, "shear-area");
  EXPECT_EQ(settings.targets.shear_uN_per_m, 10.15);
  EXPECT_EQ(settings.targets.overall_bending_modulus_J, 2.5e-19);
}

TEST(CalibrateSettings, EveryOptionReachesItsField) {
  const auto settings = rbcsim::setup::calibration_settings_from(resolve_config(
      {.assignments = {
           "calibrate.fits=bend", "calibrate.patch_edge=force-length-scale",
           "calibrate.strain=0.002", "calibrate.angle_rad=0.004",
           "calibrate.area_difference_per_total_curvature=2",
           "calibrate.target.moduli=young-poisson", "calibrate.target.shear_modulus_uN_per_m=6",
           "calibrate.target.area_modulus_uN_per_m=15",
           "calibrate.target.young_modulus_uN_per_m=20", "calibrate.target.poisson_ratio=0.4",
           "calibrate.target.bending_modulus_J=1e-19",
           "calibrate.target.overall_bending_modulus_J=3e-19",
           "calibrate.stretch_fit.relative_tolerance=0.05", "stretch.contact.rigid=true",
           "stretch.forces_pN=0:40:20"}}));
  EXPECT_EQ(settings.fits, std::vector<std::string>{"bend"});
  EXPECT_EQ(settings.patch_edge, "force-length-scale");
  EXPECT_EQ(settings.strain, 0.002);
  EXPECT_EQ(settings.angle_rad, 0.004);
  EXPECT_EQ(settings.area_difference_per_total_curvature, 2.0);
  const auto& targets = settings.targets;
  EXPECT_EQ(targets.moduli, "young-poisson");
  EXPECT_EQ(targets.shear_uN_per_m, 6.0);
  EXPECT_EQ(targets.area_uN_per_m, 15.0);
  EXPECT_EQ(targets.young_uN_per_m, 20.0);
  EXPECT_EQ(targets.poisson_ratio, 0.4);
  EXPECT_EQ(targets.bending_modulus_J, 1e-19);
  EXPECT_EQ(targets.overall_bending_modulus_J, 3e-19);
  // The stretch fit: its tolerance, the stretch as configured, Mills et al.'s 13 forces.
  const auto& stretch_fit = settings.stretch_fit;
  EXPECT_EQ(stretch_fit.relative_tolerance, 0.05);
  EXPECT_TRUE(stretch_fit.stretch.contact.rigid);
  EXPECT_EQ(stretch_fit.stretch.forces_pN, (std::vector<double>{0.0, 20.0, 40.0}));
  EXPECT_EQ(stretch_fit.reference.size(), 13u);
}

TEST(CalibrateSettings, OutOfRangeAndUnknownValuesAreInputErrors) {
  EXPECT_THROW(resolve_config({.assignments = {"calibrate.target.poisson_ratio=1"}}),
               rbcsim::InputError);
  EXPECT_THROW(resolve_config({.assignments = {"calibrate.fits=bend,stretchiness"}}),
               rbcsim::InputError);
  EXPECT_THROW(resolve_config({.assignments = {"calibrate.strain=0"}}), rbcsim::InputError);
}

}  // namespace
