// The calibrate stretch fit on a coarse cell (162 vertices, seconds): it recovers the k_link that
// made a curve, and it says so when the misfit has no minimum; its table marks a failed curve.
#include "cases/stretch_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cases/stretch_output.hpp"
#include "common/errors.hpp"
#include "mesh/cell_shapes.hpp"
#include "support/relative_difference.hpp"

namespace {

using rbcsim::cases::StretchFitSettings;
using rbcsim::cases::StretchReferencePoint;
using rbcsim::membrane::MembraneParameters;

const auto& coarse_discocyte() {
  static const auto cell = rbcsim::mesh::generate_cell("discocyte", 2);
  return cell;
}

StretchFitSettings rigid_contact_settings() {
  StretchFitSettings settings;
  settings.stretch.contact.rigid = true;
  settings.stretch.forces_pN = {0.0, 10.0, 20.0};
  settings.relative_tolerance = 1e-3;
  return settings;
}

// The curve at `k_link_kBT` (forces 0, 10, 20 pN), as a measurement with bars of +- 0.1 um.
std::vector<StretchReferencePoint> curve_as_measured(double k_link_kBT) {
  const auto stretch = rigid_contact_settings().stretch;
  MembraneParameters parameters;
  parameters.k_link_kBT = k_link_kBT;
  const auto cell = rbcsim::cases::prepare_stretch_cell(coarse_discocyte(), stretch.contact);
  const rbcsim::membrane::MembraneModel model(cell.mesh, parameters);
  std::vector<StretchReferencePoint> measured;
  for (const auto& point : rbcsim::cases::run_stretch(model, cell, stretch, {}).points) {
    EXPECT_TRUE(point.converged);
    measured.push_back(
        {point.force_pN,
         {point.axial_um, point.axial_um - 0.1, point.axial_um + 0.1},
         {point.transverse_um, point.transverse_um - 0.1, point.transverse_um + 0.1}});
  }
  return measured;
}

// From Table 2's k_link = 7 to the 4.2 that made the curve: within 1 % (the fit's tolerance is
// 0.1 %), every point inside its bar.
TEST(StretchFit, RecoversTheLinkStiffnessThatMadeTheCurve) {
  auto settings = rigid_contact_settings();
  settings.reference = curve_as_measured(4.2);
  const MembraneParameters table2;
  const auto fit = rbcsim::cases::fit_stretch_k_link(coarse_discocyte(), table2, settings);
  EXPECT_EQ(fit.start_k_link_kBT, 7.0);
  EXPECT_LT(rbcsim::testing::relative_difference(fit.best.k_link_kBT, 4.2), 0.01);
  EXPECT_EQ(fit.best.comparison.inside_error_bars, 3u);
  EXPECT_LT(fit.best.misfit, 0.01);
  EXPECT_LE(fit.evaluations.size(), 20u);
  for (const auto& evaluation : fit.evaluations) EXPECT_GE(evaluation.misfit, fit.best.misfit);
}

// A "measurement" that never deforms wants an infinitely stiff membrane: the misfit falls for
// ever, and the fit fails rather than report the last k_link tried.
TEST(StretchFit, FailsWhenTheMisfitHasNoMinimum) {
  auto settings = rigid_contact_settings();
  settings.max_evaluations = 6;
  for (const double force_pN : {0.0, 10.0, 20.0}) {
    settings.reference.push_back({force_pN, {7.82, 7.72, 7.92}, {7.82, 7.72, 7.92}});
  }
  EXPECT_THROW(
      rbcsim::cases::fit_stretch_k_link(coarse_discocyte(), MembraneParameters{}, settings),
      rbcsim::RuntimeFailure);
}

// The fit's curves relax with its own budget, not the stretch's: with too few iterations per
// force every curve fails (each counted as failed, never as a shape), and the fit with them.
TEST(StretchFit, CurvesRelaxWithinTheFitsOwnIterationBudget) {
  auto settings = rigid_contact_settings();
  settings.reference = curve_as_measured(4.2);
  settings.max_evaluations = 4;
  settings.max_iterations_per_force = 10;
  ASSERT_GT(settings.stretch.relaxation_settings.max_iterations, 1000u);
  std::vector<rbcsim::cases::StretchFitEvaluation> seen;
  settings.on_evaluation = [&seen](const auto& evaluation) { seen.push_back(evaluation); };
  EXPECT_THROW(
      rbcsim::cases::fit_stretch_k_link(coarse_discocyte(), MembraneParameters{}, settings),
      rbcsim::RuntimeFailure);
  ASSERT_FALSE(seen.empty());
  for (const auto& evaluation : seen) {
    EXPECT_TRUE(std::isinf(evaluation.misfit));
    EXPECT_NE(evaluation.failure.find("not converged after 10 iterations"), std::string::npos)
        << evaluation.failure;
  }
}

// Forces below the first loaded reference force compare nothing but the rest shape, which no
// k_link changes: bad input, found before any curve is run.
TEST(StretchFit, RefusesForcesThatSpanNoLoadedReferenceForce) {
  auto settings = rigid_contact_settings();
  settings.reference = {{0.0, {7.82, 7.72, 7.92}, {7.82, 7.72, 7.92}},
                        {30.0, {10.0, 9.0, 11.0}, {6.0, 5.0, 7.0}}};
  settings.stretch.forces_pN = {0.0, 10.0, 20.0};
  try {
    rbcsim::cases::fit_stretch_k_link(coarse_discocyte(), MembraneParameters{}, settings);
    FAIL() << "no InputError";
  } catch (const rbcsim::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("stretch.forces_pN"), std::string::npos);
  }
}

// A failed curve measured nothing: its row says so (misfit inf, RMS nan), never a zero deviation
// that would read as a perfect fit.
TEST(StretchFit, TableRowOfAFailedCurveMeasuresNothing) {
  rbcsim::cases::StretchFitEvaluation failed{.k_link_kBT = 2.5,
                                             .misfit = std::numeric_limits<double>::infinity(),
                                             .comparison = {},
                                             .failure = "F = 192.7 pN: vertex force cap",
                                             .wall_time_s = 3.0};
  const auto row = rbcsim::cases::stretch_fit_table_row(failed);
  ASSERT_EQ(row.size(), rbcsim::cases::stretch_fit_table_columns().size());
  EXPECT_EQ(row[0], 2.5);
  EXPECT_TRUE(std::isinf(row[1]));
  EXPECT_TRUE(std::isnan(row[2]));
  EXPECT_TRUE(std::isnan(row[3]));
  EXPECT_EQ(row[4], 0.0);
  EXPECT_EQ(row[5], 3.0);
}

}  // namespace
