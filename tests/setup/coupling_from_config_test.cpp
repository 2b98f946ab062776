// lattice.*, physics.cytoplasm_viscosity_ratio, ibm.*, stability.* and output.* options reach the
// fluid's and the coupled loop's structs, and output intervals in seconds become whole numbers of
// steps.
#include "setup/coupling_from_config.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/config.hpp"
#include "parallel/hdf5_file.hpp"
#include "support/files.hpp"
#include "support/scratch_directory.hpp"

namespace {

using rbcsim::config::resolve_config;

TEST(CouplingFromConfig, DefaultsAndOverridesReachTheStructs) {
  const auto defaults = rbcsim::setup::coupling_parameters_from(resolve_config(), "run");
  EXPECT_EQ(defaults.kernel, "phi2");
  EXPECT_EQ(defaults.point_advance, "euler");
  EXPECT_DOUBLE_EQ(defaults.stability.max_vertex_step_lu, 0.5);  // half a spacing (docs/physics.md)
  EXPECT_EQ(defaults.run_directory, "run");

  const auto config = resolve_config(
      {.assignments = {"ibm.kernel=phi4", "ibm.point_advance=ab2",
                       "stability.max_vertex_step_dx=0.25",
                       "stability.force_cap_vertex_fraction=0.2", "stability.force_cap_max_steps=7",
                       "stability.fluid_check_interval_steps=9", "lattice.collision=bgk",
                       "lattice.relaxation_time=0.8", "physics.cytoplasm_viscosity_ratio=5"}});
  const auto parameters = rbcsim::setup::coupling_parameters_from(config, "");
  EXPECT_EQ(parameters.kernel, "phi4");
  EXPECT_EQ(parameters.point_advance, "ab2");
  EXPECT_DOUBLE_EQ(parameters.stability.max_vertex_step_lu, 0.25);
  EXPECT_DOUBLE_EQ(parameters.stability.force_cap_vertex_fraction, 0.2);
  EXPECT_EQ(parameters.stability.force_cap_max_steps, 7u);
  EXPECT_EQ(parameters.stability.fluid_check_interval_steps, 9u);
  const auto fluid = rbcsim::setup::fluid_parameters_from(config);
  EXPECT_EQ(fluid.collision, "bgk");
  EXPECT_DOUBLE_EQ(fluid.collision_parameters.tau, 0.8);
  EXPECT_DOUBLE_EQ(fluid.collision_parameters.magic_parameter, 3.0 / 16.0);
  EXPECT_EQ(fluid.inner_viscosity_ratio, 5.0);
  EXPECT_EQ(rbcsim::setup::fluid_parameters_from(resolve_config()).inner_viscosity_ratio, 1.0);
  EXPECT_THROW(resolve_config({.assignments = {"physics.cytoplasm_viscosity_ratio=0"}}),
               rbcsim::InputError);
}

TEST(CouplingFromConfig, SnapshotIntervalsAreRoundedToWholeSteps) {
  // dt = (tau - 1/2)/3 dx^2 / nu with the defaults dx = 0.5 um, tau = 1, nu = 1.1e-6 m^2/s.
  const double dt_s = (0.5 / 3.0) * 0.25e-12 / 1.1e-6;
  const auto config = resolve_config(
      {.assignments = {"output.membrane_interval_s=" + rbcsim::format_number(100.4 * dt_s),
                       "output.fluid_interval_s=0"}});
  const auto intervals =
      rbcsim::setup::snapshot_intervals_from(config, rbcsim::config::make_unit_converter(config));
  EXPECT_EQ(intervals.membrane_steps, 100u);
  EXPECT_EQ(intervals.fluid_steps, 0u);  // off
  const auto tiny = resolve_config({.assignments = {"output.fluid_interval_s=1e-12"}});
  EXPECT_EQ(rbcsim::setup::snapshot_intervals_from(tiny, rbcsim::config::make_unit_converter(tiny))
                .fluid_steps,
            1u);  // at least every step
}

// auto: VTK on one process (this test), and on a resume the format of the series already in the
// run directory, so that a run checkpointed on several processes (HDF5) goes on in HDF5.
TEST(CouplingFromConfig, AutomaticSnapshotFormatFollowsTheSeriesOfTheRunDirectory) {
  using rbcsim::coupling::SnapshotFormat;
  const rbcsim::testing::ScratchDirectory scratch;
  const auto config = resolve_config();
  EXPECT_EQ(rbcsim::setup::snapshot_format_from(config, scratch.path()), SnapshotFormat::vtk);
  EXPECT_EQ(rbcsim::setup::snapshot_format_from(
                resolve_config({.assignments = {"output.format=vtk"}}), scratch.path()),
            SnapshotFormat::vtk);
  rbcsim::testing::write_file(scratch.path() / "fluid.xdmf", "<Xdmf/>\n");
  if (rbcsim::parallel::built_with_hdf5()) {
    EXPECT_EQ(rbcsim::setup::snapshot_format_from(config, scratch.path()), SnapshotFormat::hdf5);
    EXPECT_EQ(rbcsim::setup::snapshot_format_from(
                  resolve_config({.assignments = {"output.format=hdf5"}})),
              SnapshotFormat::hdf5);
  } else {
    EXPECT_THROW(rbcsim::setup::snapshot_format_from(config, scratch.path()), rbcsim::InputError);
    EXPECT_THROW(rbcsim::setup::snapshot_format_from(
                     resolve_config({.assignments = {"output.format=hdf5"}})),
                 rbcsim::InputError);
  }
  // An explicit choice is not overridden by what the directory holds.
  EXPECT_EQ(rbcsim::setup::snapshot_format_from(
                resolve_config({.assignments = {"output.format=vtk"}}), scratch.path()),
            SnapshotFormat::vtk);
}

TEST(CouplingFromConfig, UnknownIbmNamesAreRefusedByTheConfig) {
  EXPECT_THROW(resolve_config({.assignments = {"ibm.point_advance=rk4"}}), rbcsim::InputError);
  EXPECT_THROW(resolve_config({.assignments = {"stability.max_vertex_step_dx=0"}}),
               rbcsim::InputError);
}

}  // namespace
