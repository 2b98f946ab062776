// stretch.* options -> cases::StretchSettings, and the forces text.
#include "setup/stretch_from_config.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"

namespace {

using rbcsim::setup::stretch_forces_from;

std::string forces_error(const std::string& text) {
  try {
    stretch_forces_from(text, "--forces");
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(StretchFromConfig, DefaultsAreTheMillsForcesAndTheTwoMicrometreContact) {
  const auto settings = rbcsim::setup::stretch_settings_from(rbcsim::config::resolve_config());
  EXPECT_EQ(settings.mode, "quasi-static");
  ASSERT_EQ(settings.forces_pN.size(), 13u);
  EXPECT_EQ(settings.forces_pN.front(), 0.0);
  EXPECT_DOUBLE_EQ(settings.forces_pN.back(), 192.688);
  EXPECT_EQ(settings.contact.rule, "contact-diameter");
  EXPECT_EQ(settings.contact.diameter_um, 2.0);
  EXPECT_EQ(settings.relaxation, "fire");
  EXPECT_EQ(settings.relaxation_settings.force_tolerance_pN, 1e-4);
}

TEST(StretchFromConfig, OverridesReachTheSettings) {
  const auto config = rbcsim::config::resolve_config(
      {.assignments = {"stretch.forces_pN=0:200:50", "stretch.contact.rule=extreme-vertices",
                       "stretch.contact.extreme_vertex_count=12", "stretch.contact.rigid=true",
                       "stretch.quasi_static.relaxation=euler",
                       "stretch.quasi_static.max_iterations=77"}});
  const auto settings = rbcsim::setup::stretch_settings_from(config);
  EXPECT_EQ(settings.forces_pN, (std::vector<double>{0, 50, 100, 150, 200}));
  EXPECT_EQ(settings.contact.rule, "extreme-vertices");
  EXPECT_EQ(settings.contact.extreme_vertex_count, 12);
  EXPECT_TRUE(settings.contact.rigid);
  EXPECT_EQ(settings.relaxation, "euler");
  EXPECT_EQ(settings.relaxation_settings.max_iterations, 77u);
}

TEST(StretchFromConfig, ForcesTextIsARangeOrTheReference) {
  EXPECT_EQ(stretch_forces_from("0:200", "x").size(), 9u);  // every 25 pN
  EXPECT_EQ(stretch_forces_from("10,5", "x"), (std::vector<double>{10, 5}));
  EXPECT_EQ(forces_error("-5:10:5"), "--forces: forces must be >= 0 pN (the tweezers pull)");
  EXPECT_EQ(forces_error("abc"), "--forces: range \"abc\": \"abc\" is not a number");
  EXPECT_THROW(rbcsim::config::resolve_config({.assignments = {"stretch.mode=molten"}}),
               rbcsim::InputError);
}

// The fluid mode's lattice takes dx, tau and the density from lattice.* and physics.*, but its
// own viscosity; the steady criterion, time limit, ramp, margin and snapshots from stretch.fluid.*.
TEST(StretchFromConfig, FluidModeSettings) {
  const auto config = rbcsim::config::resolve_config(
      {.assignments = {
           "stretch.mode=fluid", "lattice.spacing_um=1",
           "physics.plasma_kinematic_viscosity_m2_per_s=2e-6",
           "stretch.fluid.kinematic_viscosity_m2_per_s=3e-7", "stretch.fluid.box_margin_um=4",
           "stretch.fluid.steady_relative_rate_per_s=0.2",
           "stretch.fluid.steady_check_interval_s=1e-4", "stretch.fluid.max_time_per_force_s=0.5",
           "stretch.fluid.force_ramp_time_s=0", "stretch.fluid.snapshot_interval_s=1e-3",
           "ibm.kernel=phi4"}});
  const auto settings = rbcsim::setup::stretch_settings_from(config);
  EXPECT_EQ(settings.mode, "fluid");
  const auto& fluid = settings.fluid;
  EXPECT_EQ(fluid.lattice.spacing_um, 1.0);
  EXPECT_EQ(fluid.lattice.relaxation_time, 1.0);
  EXPECT_EQ(fluid.lattice.density_kg_per_m3, 1025.0);
  EXPECT_EQ(fluid.lattice.kinematic_viscosity_m2_per_s, 3e-7);
  EXPECT_EQ(fluid.box_margin_um, 4.0);
  EXPECT_EQ(fluid.steady.relative_rate_per_s, 0.2);
  EXPECT_EQ(fluid.steady.check_interval_s, 1e-4);
  EXPECT_EQ(fluid.max_time_per_force_s, 0.5);
  EXPECT_EQ(fluid.force_ramp_time_s, 0.0);
  EXPECT_EQ(fluid.snapshot_interval_s, 1e-3);
  EXPECT_EQ(fluid.coupling.kernel, "phi4");
  EXPECT_EQ(fluid.fluid.collision, "trt");
  EXPECT_TRUE(fluid.output_directory.empty());
}

}  // namespace
