// Long physics check (label `validate`, not in the default suite): the fluid-coupled stretch of
// the discocyte, all six terms, the 13 forces of Mills et al. (2004), one simulation per curve.
// Asserts that every force reaches a steady state, that the curve is monotonic and that it lies
// on the quasi-static equilibria (the same physics); prints the curve, its distance from the
// measurements, steps and wall time.
//
// Measured (docs/validation.md, "Fluid-coupled curves"): at the paper's pairing (2562 vertices,
// 0.25 um edges on dx = 0.5 um) each force takes 129k-285k steps and the run fails at 108.9 pN, the
// 9th force, at the local-area limit after 1.5 h on one thread: edges half a spacing long do not
// hold in sustained flow (as in the capillary). With edges about one spacing (642 vertices on
// dx = 0.75 um) the curve reaches all 13 forces: 1.07 M steps, 463 s on one thread.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "cases/stretch_reference.hpp"
#include "io/csv_table.hpp"
#include "stretch_test_support.hpp"

namespace {

namespace cases = rbcsim::cases;

void expect_fluid_curve_on_the_quasi_static_one(int mesh_level,
                                                const rbcsim::membrane::MembraneParameters& terms,
                                                double lattice_spacing_um) {
  const auto reference = cases::stretch_reference_from(rbcsim::io::read_csv_file(
      std::string(RBCSIM_SOURCE_DIR) + "/share/reference/mills2004_stretch.csv"));
  const auto cell = cases::prepare_stretch_cell(cases::testing::evans_fung_discocyte(mesh_level), {});
  const rbcsim::membrane::MembraneModel model(cell.mesh, terms);
  cases::StretchSettings settings;
  for (const auto& measured : reference) settings.forces_pN.push_back(measured.force_pN);
  settings.mode = "fluid";
  settings.fluid.lattice.spacing_um = lattice_spacing_um;

  const auto start = std::chrono::steady_clock::now();
  const auto fluid = cases::run_stretch(model, cell, settings, {});
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(fluid.ok()) << fluid.failure;
  settings.mode = "quasi-static";
  const auto quasi_static = cases::run_stretch(model, cell, settings, {});
  ASSERT_TRUE(quasi_static.ok()) << quasi_static.failure;

  std::printf(
      " force_pN  axial_um (quasi-static, Mills)  transverse_um (quasi-static, Mills)   steps"
      "   max Mach  max Re\n");
  std::size_t steps = 0;
  for (std::size_t i = 0; i < fluid.points.size(); ++i) {
    const auto& p = fluid.points[i];
    const auto& q = quasi_static.points[i];
    steps += p.steps;
    std::printf(
        "%9.3f  %7.3f (%7.3f, %6.3f)          %7.3f (%7.3f, %6.3f)           %7zu  %.2e  %.2e\n",
        p.force_pN, p.axial_um, q.axial_um, reference[i].axial.mean_um, p.transverse_um,
        q.transverse_um, reference[i].transverse.mean_um, p.steps, p.max_mach_number,
        p.max_reynolds_number);
    // The steady criterion stops short of the equilibrium by rate * D * tau_slow
    // (fluid_stretch_test.cpp); over the level-2 curve this lag grew with the force to 0.41 um
    // axial at 130 pN (0.19 um transverse): 0.5 um allowed.
    EXPECT_NEAR(p.axial_um, q.axial_um, 0.5) << p.force_pN;
    EXPECT_NEAR(p.transverse_um, q.transverse_um, 0.5) << p.force_pN;
    EXPECT_LT(p.max_mach_number, 0.1) << p.force_pN;
  }
  char run_summary[64];
  std::snprintf(run_summary, sizeof run_summary, "%zu steps, wall time %.1f s", steps, wall_s);
  cases::testing::expect_and_print_mills_comparison(fluid.points, reference, run_summary);
}

// The paper's cell, lattice and Table 2 as printed: fails at 108.9 pN as measured (above).
TEST(ValidateFluidStretch, MillsCurveAtThePapersResolution) {
  expect_fluid_curve_on_the_quasi_static_one(4, {}, 0.5);
}

// 642 vertices (0.5 um edges) on dx = 0.75 um, with Table 2's moduli: k_link and k_area doubled,
// since the link and area moduli go as k / L0 (hexagonal patch test) and L0 doubles.
TEST(ValidateFluidStretch, MillsCurveWithEdgesAboutOneSpacing) {
  rbcsim::membrane::MembraneParameters terms;
  terms.k_link_kBT *= 2.0;
  terms.k_area_kBT *= 2.0;
  expect_fluid_curve_on_the_quasi_static_one(3, terms, 0.75);
}

}  // namespace
