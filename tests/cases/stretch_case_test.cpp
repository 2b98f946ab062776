// The quasi-static stretch of the N = 3 discocyte (all six terms, Table 2): physics that must hold
// whatever the parameters.
#include "cases/stretch_case.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::cases::StretchSettings;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
namespace support = rbcsim::cases::testing;

// Work of the tweezer forces along the displacement from the stress-free shape.
double tweezer_work_pN_um(const support::ObservedState& state,
                          const std::vector<Vec3>& stress_free_um) {
  double work = 0.0;
  for (std::size_t i = 0; i < state.positions_um.size(); ++i) {
    work += state.external_forces_pN[i].dot(state.positions_um[i] - stress_free_um[i]);
  }
  return work;
}

// The stress-free shape is an equilibrium: no force, no iteration, no displacement.
void expect_zero_force_gives_zero_deformation(const support::ObservedState& at_rest,
                                              const std::vector<Vec3>& stress_free_um) {
  EXPECT_EQ(at_rest.point.iterations, 0u);
  EXPECT_EQ(at_rest.positions_um, stress_free_um);
  EXPECT_NEAR(at_rest.point.axial_um, 7.82, 1e-6);  // 2 R0 of Evans-Fung
  EXPECT_NEAR(at_rest.point.transverse_um, 7.82, 1e-6);
}

void expect_axial_grows_and_transverse_shrinks(const std::vector<support::ObservedState>& states) {
  for (std::size_t i = 1; i < states.size(); ++i) {
    EXPECT_GT(states[i].point.axial_um, states[i - 1].point.axial_um) << states[i].point.force_pN;
    EXPECT_LT(states[i].point.transverse_um, states[i - 1].point.transverse_um)
        << states[i].point.force_pN;
  }
}

// At equilibrium the membrane holds each patch against its tweezer: the membrane forces on the
// patch sum to -F (x). Exactly so (to the tolerance per vertex) for a smooth energy
// (relaxation_methods_test); with the total-curvature term the equilibrium is that of the model
// with the flat edges' sign(theta_j) smoothed (curvature_kinks.hpp), and the smoothing force of
// flat edges straddling the patch border is part of the balance: 0.1 % of F allows for it
// (measured: at most 0.06 %, at 50 pN).
void expect_patch_force_balance(const std::vector<support::ObservedState>& states,
                                const rbcsim::cases::ContactPatches& patches) {
  for (const auto& state : states) {
    Vec3 positive = Vec3::Zero();
    Vec3 negative = Vec3::Zero();
    for (const auto v : patches.positive_end) positive += state.membrane_forces_pN[v];
    for (const auto v : patches.negative_end) negative += state.membrane_forces_pN[v];
    const double force = state.point.force_pN;
    const double slack_pN = 1e-3 * force + 1e-4 * static_cast<double>(patches.positive_end.size());
    EXPECT_NEAR((positive + Vec3(force, 0, 0)).norm(), 0.0, slack_pN) << force;
    EXPECT_NEAR((negative - Vec3(force, 0, 0)).norm(), 0.0, slack_pN) << force;
  }
}

// Linear regime, two checks that need no model of the cell:
// - proportionality: half the force, half the extension;
// - Clapeyron's theorem: at equilibrium under loads f, a linear elastic body stores half the
//   work the loads did along its displacement, E = (1/2) f.u (the energy is a quadratic form Q and
//   equilibrium is grad Q = f, so f.u = u.grad Q = 2 Q). The membrane energy (the integral of the
//   six force laws, `gradient` distribution) is quadratic to leading order in the displacement;
//   the cubic terms of the force laws and the change of geometry add O(strain): measured 0.8 %
//   at 0.5 pN and 1.3 % at 1 pN, so 3 %.
void expect_linear_regime(const std::vector<support::ObservedState>& states,
                          const std::vector<Vec3>& stress_free_um) {
  const auto& rest = states[0].point;
  const auto& half = states[1];
  const auto& one = states[2];
  const double extension_half = half.point.axial_um - rest.axial_um;
  const double extension_one = one.point.axial_um - rest.axial_um;
  std::printf("extension %.5f um at 0.5 pN, %.5f um at 1 pN; energy / (work / 2): %.4f, %.4f\n",
              extension_half, extension_one,
              half.membrane_energy_pN_um / (0.5 * tweezer_work_pN_um(half, stress_free_um)),
              one.membrane_energy_pN_um / (0.5 * tweezer_work_pN_um(one, stress_free_um)));
  EXPECT_NEAR(extension_one / extension_half, 2.0, 0.05);
  for (const auto* state : {&half, &one}) {
    EXPECT_NEAR(state->membrane_energy_pN_um / (0.5 * tweezer_work_pN_um(*state, stress_free_um)),
                1.0, 0.03);
  }
}

// The low-resolution curve, in the default suite (a few seconds): two small forces for the
// linear regime, then Mills' range. One run, checked several ways.
TEST(StretchCase, LowResolutionCurve) {
  const auto cell = rbcsim::cases::prepare_stretch_cell(support::evans_fung_discocyte(3), {});
  const MembraneModel model(cell.mesh, MembraneParameters{});
  StretchSettings settings;
  settings.forces_pN = {0.0, 0.5, 1.0, 50.0, 100.0, 150.0, 200.0};
  const auto observed = support::run_and_observe(model, cell, settings);
  ASSERT_TRUE(observed.run.ok()) << observed.run.failure;
  ASSERT_EQ(observed.states.size(), settings.forces_pN.size());
  for (const auto& state : observed.states) {
    EXPECT_TRUE(state.point.converged) << state.point.force_pN;
    std::printf("F = %5.1f pN: axial %.3f um, transverse %.3f um, %zu iterations, %.2f s\n",
                state.point.force_pN, state.point.axial_um, state.point.transverse_um,
                state.point.iterations, state.point.wall_time_s);
  }
  {
    SCOPED_TRACE("zero force");
    expect_zero_force_gives_zero_deformation(observed.states.front(), cell.mesh.positions_um);
  }
  {
    SCOPED_TRACE("monotonic");
    expect_axial_grows_and_transverse_shrinks(observed.states);
  }
  {
    SCOPED_TRACE("force balance");
    expect_patch_force_balance(observed.states, cell.patches);
  }
  {
    SCOPED_TRACE("linear regime");
    expect_linear_regime(observed.states, cell.mesh.positions_um);
  }
}

// A rigid contact (the membrane glued to a bead) moves each patch as one body: every patch vertex
// has the same displacement, and the patch is in balance with the tweezers as before. The fluid
// mode cannot hold a patch rigid and says so.
TEST(StretchCase, RigidContactPatchTranslatesAsOneBody) {
  const rbcsim::cases::ContactSettings contact{.rigid = true};
  const auto cell = rbcsim::cases::prepare_stretch_cell(support::evans_fung_discocyte(3), contact);
  const MembraneModel model(cell.mesh, MembraneParameters{});
  StretchSettings settings;
  settings.contact = contact;
  settings.forces_pN = {0.0, 50.0};
  const auto observed = support::run_and_observe(model, cell, settings);
  ASSERT_TRUE(observed.run.ok()) << observed.run.failure;
  const auto& rest_um = observed.states.front().positions_um;
  const auto& pulled_um = observed.states.back().positions_um;
  for (const auto* patch : {&cell.patches.positive_end, &cell.patches.negative_end}) {
    const Vec3 shift_um = pulled_um[patch->front()] - rest_um[patch->front()];
    EXPECT_GT(std::abs(shift_um.x()), 0.5);
    for (const auto v : *patch) {
      EXPECT_NEAR((pulled_um[v] - rest_um[v] - shift_um).norm(), 0.0, 1e-9) << v;
    }
  }
  expect_patch_force_balance(observed.states, cell.patches);

  settings.mode = "fluid";
  EXPECT_THROW(rbcsim::cases::run_stretch(model, cell, settings, {}), rbcsim::InputError);
}

TEST(StretchCase, UnknownModeIsAnInputError) {
  const auto cell = rbcsim::cases::prepare_stretch_cell(support::evans_fung_discocyte(3), {});
  const MembraneModel model(cell.mesh, MembraneParameters{});
  StretchSettings settings;
  settings.mode = "fluid-someday";
  settings.forces_pN = {0.0};
  EXPECT_THROW(rbcsim::cases::run_stretch(model, cell, settings, {}), rbcsim::InputError);
  EXPECT_EQ(rbcsim::cases::stretch_mode_names(),
            (std::vector<std::string>{"quasi-static", "fluid"}));
}

// A force the relaxation cannot reach within its iteration budget stops the run with a message,
// the failed point recorded (and not converged), the later forces not attempted.
TEST(StretchCase, IterationBudgetExhaustedStopsTheRunLoudly) {
  const auto cell = rbcsim::cases::prepare_stretch_cell(support::evans_fung_discocyte(3), {});
  const MembraneModel model(cell.mesh, MembraneParameters{});
  StretchSettings settings;
  settings.forces_pN = {0.0, 40.0, 80.0};
  settings.relaxation_settings.max_iterations = 10;
  const auto run = rbcsim::cases::run_stretch(model, cell, settings, {});
  EXPECT_FALSE(run.ok());
  ASSERT_EQ(run.points.size(), 2u);
  EXPECT_TRUE(run.points[0].converged);
  EXPECT_FALSE(run.points[1].converged);
  EXPECT_EQ(run.failure.rfind("F = 40 pN: not converged after 10 iterations", 0), 0u)
      << run.failure;
}

}  // namespace
