// The fluid-coupled stretch at low resolution: the level-2 discocyte (162 vertices, all six terms,
// Table 2) at dx = 2 um (its edges are ~1 um: the paper's Lagrangian/Eulerian ratio S = 0.5), in
// a fluid of a third of plasma's viscosity (the steady shape does not depend on it; the steps to
// reach it are nine times fewer, and this cell stays stable there up to 50 pN).
#include "cases/fluid_stretch.hpp"
#include "cases/stretch_output.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "mesh/discocyte.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::cases::StretchRun;
using rbcsim::cases::StretchSettings;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
namespace cases = rbcsim::cases;

struct LowResolutionCell {
  cases::StretchCell cell = cases::prepare_stretch_cell(rbcsim::mesh::discocyte_mesh({}, 2), {});
  MembraneModel model{cell.mesh, MembraneParameters{}};
};

const LowResolutionCell& low_resolution_cell() {
  static const LowResolutionCell cell;
  return cell;
}

StretchSettings fluid_settings(std::vector<double> forces_pN) {
  StretchSettings settings;
  settings.mode = "fluid";
  settings.forces_pN = std::move(forces_pN);
  settings.fluid.lattice.spacing_um = 2.0;
  settings.fluid.lattice.kinematic_viscosity_m2_per_s = 1.1e-6 / 3.0;
  return settings;
}

StretchRun run(const StretchSettings& settings) {
  const auto& cell = low_resolution_cell();
  auto result = cases::run_stretch(cell.model, cell.cell, settings, {});
  for (const auto& p : result.points) {
    std::printf(
        "%s F = %4.1f pN: axial %.4f um, transverse %.4f um, %zu steps (%.2e s), Ma %.2e, Re "
        "%.2e, %.2f s%s\n",
        settings.mode.c_str(), p.force_pN, p.axial_um, p.transverse_um, p.steps, p.time_s,
        p.max_mach_number, p.max_reynolds_number, p.wall_time_s, p.converged ? "" : " NOT STEADY");
  }
  return result;
}

// The equilibria are the same physics: the fluid only dissipates. What separates them is how far
// the steady criterion stops short of equilibrium: it stops once the diameters drift by less than
// rate * D (0.5 /s * 12 um = 6 um/s), while the slowest mode of this cell relaxes over
// tau ~ 0.03 s in this fluid (measured: with a rate of 0.1 /s the axial diameter was still
// creeping, 0.06 um further after another 0.03 s), leaving up to rate * D * tau ~ 0.18 um,
// approached from the previous, less stretched shape. Measured 0.15 um (axial and transverse):
// 0.25 um allowed. Both modes smooth the curvature kinks alike: one model. This is the cost of
// the fluid mode, not a difference of the physics.
void expect_agreement_with_the_quasi_static_equilibrium(const StretchRun& fluid) {
  auto settings = fluid_settings({0.0, 25.0});
  settings.mode = "quasi-static";
  const auto quasi_static = run(settings);
  ASSERT_TRUE(quasi_static.ok()) << quasi_static.failure;
  EXPECT_DOUBLE_EQ(fluid.points[0].axial_um, quasi_static.points[0].axial_um);
  EXPECT_DOUBLE_EQ(fluid.points[0].transverse_um, quasi_static.points[0].transverse_um);
  EXPECT_NEAR(fluid.points[1].axial_um, quasi_static.points[1].axial_um, 0.25);
  EXPECT_NEAR(fluid.points[1].transverse_um, quasi_static.points[1].transverse_um, 0.25);
  EXPECT_LT(fluid.points[1].axial_um, quasi_static.points[1].axial_um);  // approached from below
  // Safe lattice flow: Mach well below 0.1 (compressibility errors ~ Ma^2), Stokes regime.
  EXPECT_LT(fluid.points[1].max_mach_number, 0.03);
  EXPECT_LT(fluid.points[1].max_reynolds_number, 0.5);
}

// Continuing at the same force from a steady state: the shape stays put (the restart of the
// criterion and the ramp from 25 to 25 pN do not kick it), within what the criterion allows over
// its three checks (rate * D * 3 * interval = 0.5 /s * 12 um * 6e-4 s = 0.004 um).
void expect_a_steady_state_to_stay_steady(const StretchRun& fluid) {
  EXPECT_TRUE(fluid.points[2].converged);
  EXPECT_NEAR(fluid.points[2].axial_um, fluid.points[1].axial_um, 0.004);
  EXPECT_NEAR(fluid.points[2].transverse_um, fluid.points[1].transverse_um, 0.004);
}

// A box with 5 um instead of 3 um around the cell: the steady shape is where the flow stops,
// which the periodic images hardly shift; they change how fast it is reached, and so where the
// criterion stops (the tolerance above). Measured 0.007 um: 0.05 um allowed.
void expect_a_larger_box_to_hardly_move_the_steady_shape(const StretchRun& fluid) {
  auto settings = fluid_settings({0.0, 25.0});
  settings.fluid.box_margin_um = 5.0;
  const auto larger = run(settings);
  ASSERT_TRUE(larger.ok()) << larger.failure;
  EXPECT_NEAR(larger.points[1].axial_um, fluid.points[1].axial_um, 0.05);
  EXPECT_NEAR(larger.points[1].transverse_um, fluid.points[1].transverse_um, 0.05);
}

// One fluid run, checked three ways (one test, because each ctest process would otherwise repeat
// the run): 0 pN, 25 pN, and 25 pN again (continuing from its own steady state), default margin
// (3 um).
TEST(FluidStretch, SteadyShapeIsTheEquilibriumStaysSteadyAndHardlyFeelsTheBox) {
  const auto fluid = run(fluid_settings({0.0, 25.0, 25.0}));
  ASSERT_TRUE(fluid.ok()) << fluid.failure;
  ASSERT_EQ(fluid.points.size(), 3u);
  {
    SCOPED_TRACE("against the quasi-static equilibrium");
    expect_agreement_with_the_quasi_static_equilibrium(fluid);
  }
  {
    SCOPED_TRACE("continuing at the same force");
    expect_a_steady_state_to_stay_steady(fluid);
  }
  {
    SCOPED_TRACE("in a larger box");
    expect_a_larger_box_to_hardly_move_the_steady_shape(fluid);
  }
}

// stretch.fluid.warm_start: each force starts from the quasi-static equilibrium under it, so the
// coupled run starts where the ramped one only creeps towards (the 0.15 um it stops short, above)
// and stops once the shape is steady there, in fewer steps. What may separate the two equilibria
// is the volume (the fluid holds the enclosed one, the quasi-static volume term lets it give) and
// the criterion's drift over its checks (0.004 um, above). Measured: 2e-4 um from the
// quasi-static shape after 331 steps (the criterion's three checks), the ramped run 11 771 steps
// and 0.15 um short: 0.01 um and a tenth of the steps allowed.
TEST(FluidStretch, WarmStartSettlesAtTheEquilibriumInFewerSteps) {
  auto settings = fluid_settings({0.0, 25.0});
  const auto ramped = run(settings);
  settings.fluid.warm_start = true;
  const auto warm = run(settings);
  ASSERT_TRUE(ramped.ok()) << ramped.failure;
  ASSERT_TRUE(warm.ok()) << warm.failure;
  settings.mode = "quasi-static";
  const auto quasi_static = run(settings);
  ASSERT_TRUE(quasi_static.ok()) << quasi_static.failure;
  ASSERT_EQ(warm.points.size(), 2u);
  EXPECT_GT(warm.points[1].iterations, 0u);  // the relaxation ran
  EXPECT_EQ(warm.points[1].warm_start, cases::WarmStart::converged);
  EXPECT_EQ(ramped.points[1].warm_start, cases::WarmStart::off);
  EXPECT_NEAR(warm.points[1].axial_um, quasi_static.points[1].axial_um, 0.01);
  EXPECT_NEAR(warm.points[1].transverse_um, quasi_static.points[1].transverse_um, 0.01);
  EXPECT_TRUE(warm.points[1].converged);
  EXPECT_LT(warm.points[1].steps, ramped.points[1].steps / 10);
}

// A warm start whose relaxation does not converge leaves the shape and ramps the force, as
// without the option, and says so: each point's start and the fallbacks' count in result.json.
TEST(FluidStretch, AWarmStartThatDoesNotConvergeRampsTheForceAndIsReported) {
  auto settings = fluid_settings({0.0, 25.0});
  settings.fluid.warm_start = true;
  settings.relaxation_settings.max_iterations = 3;  // far too few to converge
  const auto result = run(settings);
  ASSERT_TRUE(result.ok()) << result.failure;
  ASSERT_EQ(result.points.size(), 2u);
  EXPECT_EQ(result.points[1].warm_start, cases::WarmStart::not_converged);
  EXPECT_EQ(result.points[1].iterations, 0u);  // no warm start was used
  EXPECT_TRUE(result.points[1].converged);     // the ramped force reached its steady shape
  const auto json = cases::stretch_result_section("fluid", {}, result.points, {});
  EXPECT_EQ(json["points"][1]["start"], "ramped: the warm start did not converge");
  // At zero force the stress-free shape is its own equilibrium: that start is warm.
  EXPECT_EQ(json["points"][0]["start"], "warm");
  EXPECT_EQ(json["warm_start_fallbacks"], 1);
}

// A force not steady within its time is reported, not accepted: converged false, the run goes on
// to the next force (one simulation) and fails at the end naming the force.
TEST(FluidStretch, AForceNotSteadyInTimeIsReported) {
  auto settings = fluid_settings({0.0, 25.0, 30.0});
  settings.fluid.max_time_per_force_s = 2e-3;
  const auto result = run(settings);
  ASSERT_EQ(result.points.size(), 3u);
  EXPECT_TRUE(result.points[0].converged);
  EXPECT_FALSE(result.points[1].converged);
  EXPECT_FALSE(result.points[2].converged);
  EXPECT_EQ(result.failure.rfind("F = 25, 30 pN: the diameters were not steady after 0.002 s", 0),
            0u)
      << result.failure;
}

// Periodic: n nodes span n dx. Each axis spans the cell's extent (twice it along the pull) plus
// two margins, rounded up to whole spacings, centred on the cell.
TEST(FluidStretch, TheBoxHoldsTheCellWithItsMarginAndTwiceItsLength) {
  const auto& positions_um = low_resolution_cell().cell.mesh.positions_um;
  const double dx_um = 0.5;
  const double margin_um = 3.0;
  const auto box = cases::stretch_box(positions_um, dx_um, margin_um);
  for (int axis = 0; axis < 3; ++axis) {
    double low = positions_um.front()[axis];
    double high = low;
    for (const auto& p : positions_um) {
      low = std::min(low, p[axis]);
      high = std::max(high, p[axis]);
    }
    const double needed_um = (axis == 0 ? 2.0 : 1.0) * (high - low) + 2.0 * margin_um;
    const double span_um = dx_um * box.nodes[static_cast<std::size_t>(axis)];
    EXPECT_GE(span_um, needed_um) << axis;
    EXPECT_LT(span_um, needed_um + dx_um) << axis;
    const double centre_um = box.origin_um[axis] + 0.5 * (span_um - dx_um);
    EXPECT_NEAR(centre_um, 0.5 * (low + high), 1e-12) << axis;
  }
}

}  // namespace
