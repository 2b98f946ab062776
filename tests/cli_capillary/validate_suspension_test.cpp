// Blood in a straight tube against the in-vitro fits of Pries et al.: the relative apparent
// viscosity (1992, Am J Physiol 263:H1770) and the Fahraeus ratio H_T/H_D (1990, Circ Res 67:826),
// both at the run's own measured discharge hematocrit. Long (about an hour on 2 cores for the
// 10 um tube): label `validate`, run with ctest -L validate.
//
// What makes a run a comparison, not a number: the flow must have developed (the cells carried
// 25 tube diameters or more; Chien et al. need 25-50 for the Fahraeus-Lindqvist effect to
// establish), no two cells may have passed through each other in any sample, and the run must end
// by its duration (exit 0). The physiological preset (Helfrich bending, membrane viscosity, the
// bilayer's area, a viscous cytoplasm) and 2562-vertex cells: the paper's membrane fails in this
// tube within 2-7 ms.
//
// The time scale is compressed up to a Reynolds number of 0.5 (suspension.max_reynolds_number;
// physical Re 0.018): a 642-vertex run at 0.5 followed the one at 0.2 within 0.15 % in viscosity
// over 13 ms, in 2.5 times fewer steps (docs/validation.md, suspensions).
//
// Fails today (7 December 2026): with the paper's bending a cell's rim folded past its 30 degree
// limit after 41 ms; with the physiological preset's Helfrich bending and local area since, the
// flow ran 141.9 ms (23.5 D) at 1.34 x Pries' viscosity, then a triangle drifting finer than the
// lattice reached the paper's area limit (docs/validation.md, suspensions). On dx 0.25 um
// (7 December) it ran 57.7 ms (12 D), 1.08 x Pries at 4-7 D and 1.12 x at the end, before one
// cell's rim, its vertices held at the force cap, reached the same limit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "report/reference_data.hpp"
#include "support/run_rbcsim.hpp"
#include "support/run_result.hpp"
#include "support/scratch_directory.hpp"

namespace {

using rbcsim::testing::printed_run_result;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

constexpr double kDevelopedTravel_diameters = 25.0;

// The tube suspension's result section after a run of `duration_s` of physical time; the caller's
// assertions then read it.
nlohmann::json tube_flow(double diameter_um, double length_um, double tube_hematocrit,
                         double duration_s, const ScratchDirectory& scratch) {
  const auto run_dir = scratch.path() / "run";
  const auto command =
      "capillary --geometry tube --diameter-um " + std::to_string(diameter_um) + " --length-um " +
      std::to_string(length_um) + " --hematocrit " + std::to_string(tube_hematocrit) +
      " --preset physiological --set suspension.duration_s=" + std::to_string(duration_s) +
      " --set suspension.max_reynolds_number=0.5 --set suspension.averaging_fraction=0.25 "
      "--set suspension.sample_interval_s=0.0005 --set output.membrane_interval_s=0.02 "
      "--set output.fluid_interval_s=0.08 --threads 2 --json --output '" +
      run_dir.string() + "'";
  const auto result = run_rbcsim(command, scratch.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  if (result.exit_code != 0) return nullptr;
  const auto suspension = printed_run_result(result, run_dir, "capillary")["suspension"];
  std::printf(
      "D %.3g um: eta_rel %.4f +- %.4f, H_T %.4f, H_D %.4f, cell-free layer %.3f um, "
      "travel %.1f D, pierced samples %d\n",
      diameter_um, suspension["relative_apparent_viscosity"].get<double>(),
      suspension["relative_apparent_viscosity_sd"].get<double>(),
      suspension["tube_hematocrit"].get<double>(), suspension["discharge_hematocrit"].get<double>(),
      suspension["cell_free_layer_um"].get<double>(),
      suspension["cell_travel_tube_diameters"].get<double>(),
      suspension["samples_with_pierced_cells"].get<int>());
  return suspension;
}

void expect_pries_within_fifteen_percent(const nlohmann::json& suspension, double diameter_um) {
  ASSERT_FALSE(suspension.is_null());
  ASSERT_GE(suspension["cell_travel_tube_diameters"].get<double>(), kDevelopedTravel_diameters)
      << "not developed";
  ASSERT_EQ(suspension["samples_with_pierced_cells"], 0);
  const double discharge = suspension["discharge_hematocrit"].get<double>();
  const double viscosity_ratio =
      suspension["relative_apparent_viscosity"].get<double>() /
      rbcsim::report::pries1992_relative_apparent_viscosity(diameter_um, discharge);
  const double fahraeus_ratio =
      suspension["tube_to_discharge_hematocrit"].get<double>() /
      rbcsim::report::pries1990_tube_to_discharge_hematocrit(diameter_um, discharge);
  std::printf("rbcsim / Pries: viscosity %.3f, H_T/H_D %.3f\n", viscosity_ratio, fahraeus_ratio);
  EXPECT_LE(std::abs(viscosity_ratio - 1.0), rbcsim::report::kPriesAgreement);
  EXPECT_LE(std::abs(fahraeus_ratio - 1.0), rbcsim::report::kPriesAgreement);
}

// Five physiological discocytes in a 10 x 30 um tube at H_T 0.2, 2 mm/s (pseudo-shear rate
// 200 1/s), 0.16 s: the cells carry some 25 diameters, and the last quarter is averaged.
TEST(ValidateSuspension, TenMicronTubeMatchesPriesOnceDeveloped) {
  const ScratchDirectory scratch;
  const auto suspension = tube_flow(10.0, 30.0, 0.2, 0.16, scratch);
  expect_pries_within_fifteen_percent(suspension, 10.0);
}

}  // namespace
