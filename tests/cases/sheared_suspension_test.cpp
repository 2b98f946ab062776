// The sheared suspension (cases/sheared_suspension.hpp): its relative viscosity, from the
// stresslet of the forces the cells put into the fluid, against the wall stress measured
// independently from the velocity gradient next to the walls. With one cell in mid-gap no force
// reaches the fluid layers next to a wall, where the plane-averaged momentum balance makes the
// two equal in the time average (the identity the stress is built on); a wrong sign, a missing
// factor or a force left out of the sum breaks it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cases/sheared_suspension.hpp"
#include "config/config.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/suspension_from_config.hpp"

namespace rbcsim::cases {
namespace {

// One coarse discocyte (162 vertices, dx = 1 um) in mid-gap, its axis along the gradient, in a
// 23 um gap of a 16 x 16 um periodic box, at a physical 200 1/s (compressed as the command does).
ShearedSuspensionRun one_cell_in_mid_gap(std::vector<std::string> assignments) {
  for (
      const char* assignment :
      {"mesh.subdivisions=2", "mesh.method=parametric", "lattice.spacing_um=1",
       "suspension.contact_range_um=1.75", "suspension.strain=6",
       R"(suspension.cells=[{"morphology": "discocyte", "centre_um": [8, 0, 8], "axis": [0, 1, 0]}])"}) {
    assignments.emplace_back(assignment);
  }
  const config::ConfigRequest request{.assignments = assignments};
  const auto config = config::resolve_config(request);
  const double diameter_um = 7.82;
  const double rate_per_s = 200.0;
  const double factor =
      setup::sheared_suspension_compression_from(config, rate_per_s, diameter_um).factor;
  const auto simulated = setup::compressed_suspension_config(config, factor);
  const auto mix = setup::suspension_mix_from(simulated);
  const auto morphologies = setup::suspension_morphologies_from(request, mix, factor);
  const SuspensionPhysics physics{setup::fluid_parameters_from(simulated),
                                  setup::coupling_parameters_from(simulated, {}),
                                  config::make_unit_converter(simulated)};
  auto settings =
      setup::sheared_suspension_settings_from(simulated, diameter_um, rate_per_s * factor);
  settings.gap_um = 23.0;
  settings.length_um = settings.width_um = 16.0;
  const std::vector<std::size_t> cells{0};
  return run_sheared_suspension(morphologies, cells, physics, settings);
}

void expect_stresslet_equals_wall_stress(const ShearedSuspensionRun& run) {
  ASSERT_TRUE(run.ok()) << run.failure;
  ASSERT_GT(run.averaged_samples, 20u);
  EXPECT_EQ(run.samples.front().relative_viscosity, 1.0);  // the undisturbed start
  // The cell must add a measurable stress for the comparison to mean anything (volume fraction
  // 0.015: Einstein's rigid spheres would add 0.038).
  EXPECT_GT(run.relative_viscosity - 1.0, 0.02);
  // Equal in the steady mean; the tumbling cell's stress oscillates, and the last half of the
  // run holds a whole number of its periods only approximately: 5 % of the added viscosity.
  EXPECT_NEAR(run.relative_viscosity, run.near_wall_relative_viscosity,
              0.05 * (run.near_wall_relative_viscosity - 1.0));
}

TEST(ShearedSuspension, StressletOfOneCellEqualsTheWallStress) {
  expect_stresslet_equals_wall_stress(one_cell_in_mid_gap({}));
}

// The membrane's viscosity reaches the fluid through its implicit friction, not through the
// spread forces: the stresslet must count it (physiological membrane, cytoplasm as plasma).
TEST(ShearedSuspension, StressletCountsTheMembraneViscositysFriction) {
  expect_stresslet_equals_wall_stress(one_cell_in_mid_gap(
      {"membrane.forces=[\"link\",\"bend\",\"area\",\"volume\",\"area_difference\","
       "\"total_curvature\",\"viscosity\"]"}));
}

}  // namespace
}  // namespace rbcsim::cases
