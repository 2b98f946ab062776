// shear.* options -> cases::ShearSettings; the medium and engine of a shear run.
#include "setup/shear_from_config.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"

namespace {

TEST(ShearFromConfig, DefaultsAreFiveRatesUpTo2000WithLeesEdwards) {
  const auto config = rbcsim::config::resolve_config();
  const auto settings = rbcsim::setup::shear_settings_from(config);
  EXPECT_EQ(settings.rates_per_s, (std::vector<double>{0, 500, 1000, 1500, 2000}));
  EXPECT_EQ(settings.boundary, "lees-edwards");
  EXPECT_EQ(settings.gap_diameters, 3.0);
  EXPECT_TRUE(settings.viscosity_scaling);
  const auto engine = rbcsim::setup::shear_engine_from(config, "run");
  EXPECT_EQ(engine.lattice.spacing_um, 0.5);
  EXPECT_EQ(engine.lattice.kinematic_viscosity_m2_per_s, 1.1e-6);
  EXPECT_EQ(engine.coupling.run_directory, "run");
}

TEST(ShearFromConfig, OverridesReachTheSettings) {
  const auto config = rbcsim::config::resolve_config(
      {.assignments = {"shear.rates_per_s=0:2000:1000", "shear.boundary=walls",
                       "shear.gap_diameters=4", "shear.max_strain=12",
                       "shear.viscosity_scaling=false",
                       "physics.plasma_kinematic_viscosity_m2_per_s=2e-5"}});
  const auto settings = rbcsim::setup::shear_settings_from(config);
  EXPECT_EQ(settings.rates_per_s, (std::vector<double>{0, 1000, 2000}));
  EXPECT_EQ(settings.boundary, "walls");
  EXPECT_EQ(settings.gap_diameters, 4.0);
  EXPECT_EQ(settings.max_strain, 12.0);
  EXPECT_FALSE(settings.viscosity_scaling);
  EXPECT_EQ(rbcsim::setup::shear_engine_from(config, {}).lattice.kinematic_viscosity_m2_per_s,
            2e-5);
}

TEST(ShearFromConfig, NegativeRatesAreRejectedNamingTheSource) {
  try {
    rbcsim::setup::shear_rates_from("-10:100/3", "--rates");
    FAIL() << "no error";
  } catch (const rbcsim::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("--rates: ", 0), 0u) << error.what();
  }
}

}  // namespace
