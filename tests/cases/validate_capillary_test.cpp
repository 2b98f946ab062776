// The paper's capillary experiments (§3.3-3.4, Figs. 12-18) with membrane edges about one lattice
// spacing long. Long (half an hour per run on one core): label `validate`, run with
// ctest -L validate.
// The paper's own pairing (the 2562-vertex cell, 0.25 um edges, on dx = 0.5 um) at the default
// velocity (the paper's Reynolds number with plasma, 6.93e-3 m/s, Ca 1.04) fails: a triangle
// reaches the local-area limit after 0.29 ms, at the same simulated time whatever the time step
// (docs/validation.md, capillary); with edges ~dx the same cell passes. At the "natural" 5e-4 m/s
// of the paper's §3.4 (Ca 0.075) the paper's pairing passes too; at its lower end, 1e-4 m/s (Ca
// 0.015), the DI peaks where the paper's does.
// The paper's results: every cell passes; the DI peaks in the narrow section and falls back after
// it; transit time discocyte < echinocyte III < stomatocyte II.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "cases/capillary_case.hpp"
#include "config/config.hpp"
#include "setup/capillary_from_config.hpp"
#include "setup/cell_from_config.hpp"

namespace rbcsim::cases {
namespace {

CapillaryRun run_with(const std::string& morphology, const std::vector<std::string>& assignments) {
  const auto config =
      config::resolve_config({.morphology = morphology, .assignments = assignments});
  const auto wall = setup::capillary_wall_from(config);
  const auto settings = setup::capillary_settings_from(config, wall);
  const auto cell = setup::cell_mesh_from(config);
  auto run = run_capillary(cell.mesh, setup::capillary_physics_from(config, wall, cell.mesh, {}),
                           settings);
  std::printf(
      "%s: transit %.6g s, DI initial %.4f peak %.4f at x = %.3g um (narrow %.3g-%.3g), final "
      "%.4f, Re %.4g, Ca %.4g, %zu steps, vertex cap on %zu steps\n",
      morphology.c_str(), run.transit_time_s.value_or(-1.0), run.initial_deformation_index,
      run.peak_deformation_index, run.peak_centroid_x_um, run.narrow_start_um, run.narrow_end_um,
      run.final_deformation_index, run.numbers.reynolds_number, run.numbers.capillary_number,
      run.steps, run.force_capped_steps);
  return run;
}

void expect_passes_and_peaks_in_the_narrow_section(const CapillaryRun& run,
                                                   const std::string& morphology) {
  ASSERT_TRUE(run.ok()) << morphology << ": " << run.failure;
  EXPECT_GT(run.peak_centroid_x_um, run.narrow_start_um) << morphology;
  EXPECT_LT(run.peak_centroid_x_um, run.narrow_end_um) << morphology;
  EXPECT_LT(run.final_deformation_index, run.peak_deformation_index) << morphology;
}

// The paper's cell and Table 2 as they are, in the validation capillary (31.2 um, throat
// 6.75 um, Re 0.0643), on dx = 0.25 um: 2562 vertices, 0.25 um edges.
TEST(ValidateCapillary, PaperCellPassesTheValidationCapillaryOnAQuarterMicronLattice) {
  const auto run =
      run_with("discocyte", {"capillary.geometry=paper-validation", "lattice.spacing_um=0.25"});
  expect_passes_and_peaks_in_the_narrow_section(run, "discocyte");
}

// The paper's cell, Table 2 and lattice as they are (2562 vertices on dx = 0.5 um), in the
// validation capillary at the velocity §3.4 calls natural for capillaries, 5e-4 m/s (the upper
// end of its 1e-4 to 5e-4 m/s). Measured: transit 9.17 ms, DI peak 1.66 at x = 16.1 um, final
// 0.95, 553 936 steps, ~23 CPU-minutes.
TEST(ValidateCapillary, PapersPairingPassesTheValidationCapillaryAtTheNaturalVelocity) {
  const auto run = run_with("discocyte", {"capillary.geometry=paper-validation",
                                          "capillary.inlet_velocity_m_per_s=5e-4"});
  expect_passes_and_peaks_in_the_narrow_section(run, "discocyte");
}

// The paper's DI curve (§3.3, Fig. 13): a peak of "around 1.45" in the narrow section and, once
// the cell has left it, "approximately" the inlet value. The peak falls with the capillary number
// (docs/validation.md, capillary: 2.07 at the Reynolds-derived 6.93e-3 m/s, 1.64 at 5e-4, 1.43 at
// 1e-4) and reaches the paper's at the lower end of §3.4's natural 1e-4 to 5e-4 m/s, Ca 0.015. The
// 642-vertex cell (edges ~dx, Table 2's moduli as in the three-morphology test below) stands in for
// the paper's 2562-vertex one, which at this velocity would take ~2 CPU-hours: the two agree to
// 1.3 % in peak DI at Ca 1.04 and 1.1 % at Ca 0.075. The tolerance, 0.05, is how precisely the
// paper's "around 1.45" can be read. Measured: peak 1.427 at x = 15.8 um, final 0.981,
// 2 824 293 steps, 53 CPU-minutes.
TEST(ValidateCapillary, DiscocyteReachesThePapersPeakDIAtTheLowNaturalVelocity) {
  const auto run = run_with(
      "discocyte", {"capillary.geometry=paper-validation", "capillary.inlet_velocity_m_per_s=1e-4",
                    "mesh.subdivisions=3", "membrane.k_link_kBT=14", "membrane.k_area_kBT=10",
                    "membrane.vertex_force_cap_pN=200"});
  expect_passes_and_peaks_in_the_narrow_section(run, "discocyte");
  constexpr double kPapersPeak = 1.45;
  constexpr double kReadingPrecision = 0.05;
  EXPECT_NEAR(run.peak_deformation_index, kPapersPeak, kReadingPrecision);
  EXPECT_NEAR(run.final_deformation_index, run.initial_deformation_index, kReadingPrecision);
}

// The three-morphology capillary (42 um, throat 6.8 um, Re 0.04) with 642-vertex cells (0.5 um
// edges) on the paper's dx = 0.5 um and Table 2's moduli: the links' k doubled (the link modulus
// goes as k_l / L0), the local area's too (measured by the hexagonal patch test, the area
// modulus also goes as k_a / L0), the vertex cap 4 x 50 pN (a vertex carries four paper
// vertices' share).
TEST(ValidateCapillary, ThreeMorphologiesPassInThePapersOrder) {
  const std::map<std::string, std::string> k_link_kBT = {
      {"discocyte", "14"}, {"echinocyte-III", "22"}, {"stomatocyte-II", "22"}};
  std::map<std::string, double> transit_s;
  for (const auto& [morphology, k_link] : k_link_kBT) {
    const auto run =
        run_with(morphology, {"capillary.geometry=paper-morphology", "mesh.subdivisions=3",
                              "membrane.k_link_kBT=" + k_link, "membrane.k_area_kBT=10",
                              "membrane.vertex_force_cap_pN=200"});
    expect_passes_and_peaks_in_the_narrow_section(run, morphology);
    if (run.transit_time_s) transit_s[morphology] = *run.transit_time_s;
  }
  ASSERT_EQ(transit_s.size(), 3u);
  EXPECT_LT(transit_s["discocyte"], transit_s["echinocyte-III"]);
  EXPECT_LT(transit_s["echinocyte-III"], transit_s["stomatocyte-II"]);
}

}  // namespace
}  // namespace rbcsim::cases
