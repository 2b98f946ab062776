// Long physics check (label `validate`, not in the default suite; minutes): the calibrate stretch
// fit at the paper's resolution (the N = 4 discocyte, all six terms, Table 2 but k_link) against
// Mills et al. (2004), with the contact patches held rigid as by glued beads. The issue's
// acceptance figure for the stretch: every Mills point inside its error bars, for both diameters,
// with parameters from `rbcsim calibrate`. With free patches no k_link does this
// (docs/validation.md, "Why the transverse diameter misses"): the transverse diameter needs a soft
// network that the free patch lets overshoot axially.
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/calibration.hpp"
#include "config/config.hpp"
#include "setup/calibrate_from_config.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/membrane_from_config.hpp"

namespace {

TEST(ValidateStretchFit, FittedLinkStiffnessPutsEveryMillsPointInsideItsErrorBars) {
  const auto config = rbcsim::config::resolve_config(
      {.assignments = {"calibrate.fits=stretch", "stretch.contact.rigid=true"}});
  const auto calibration = rbcsim::cases::run_calibration(
      rbcsim::setup::cell_mesh_from(config).mesh, rbcsim::setup::membrane_parameters_from(config),
      rbcsim::setup::calibration_settings_from(config));
  ASSERT_TRUE(calibration.stretch.has_value());
  const auto& fit = *calibration.stretch;
  const auto& comparison = fit.curve.best.comparison;
  std::printf(
      "k_link %.4g kBT (mu %.3g uN/m) after %zu curves: misfit %.3f, RMS axial %.3f um, "
      "transverse %.3f um, inside %zu of %zu\n",
      fit.curve.best.k_link_kBT, fit.achieved.shear_uN_per_m, fit.curve.evaluations.size(),
      fit.curve.best.misfit, *comparison.rms_axial_um, *comparison.rms_transverse_um,
      comparison.inside_error_bars, comparison.point_count);
  EXPECT_EQ(comparison.point_count, 13u);
  EXPECT_EQ(comparison.axial_inside_error_bar, 13u);
  EXPECT_EQ(comparison.transverse_inside_error_bar, 13u);
  // Softer than Table 2's 7 kBT, which leaves the transverse diameter outside at 10 of 13 forces.
  EXPECT_LT(fit.curve.best.k_link_kBT, 7.0);
}

}  // namespace
