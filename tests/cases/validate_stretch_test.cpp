// Long physics check (label `validate`: every test name starts with Validate, see
// tests/CMakeLists.txt; not in the default suite): the paper's resolution, the
// 13 forces of Mills et al. (2004), with all six terms and without area_difference and
// total_curvature (the paper's Fig. 8 comparison), with free contact patches (the default) and
// with patches held rigid as by a glued bead (docs/validation.md, stretch; issue #4). Asserts what
// must hold whatever the parameters; prints the curve and its distance from the measurements, which
// is a finding, not a pass/fail bound (the parameters are Table 2's, not fitted here).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <ostream>
#include <string>

#include "cases/stretch_reference.hpp"
#include "io/csv_table.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::membrane::MembraneParameters;
namespace cases = rbcsim::cases;

struct StretchVariant {
  std::vector<std::string> terms;
  bool rigid_contact = false;
};

// The variant as the test's name and ctest's listing show it: "6_terms", "6_terms_rigid_contacts".
std::string variant_name(const StretchVariant& variant) {
  return std::to_string(variant.terms.size()) + "_terms" +
         (variant.rigid_contact ? "_rigid_contacts" : "");
}

void PrintTo(const StretchVariant& variant, std::ostream* out) { *out << variant_name(variant); }

class ValidateStretch : public ::testing::TestWithParam<StretchVariant> {};

TEST_P(ValidateStretch, MillsCurveAtThePapersResolution) {
  const auto reference = cases::stretch_reference_from(rbcsim::io::read_csv_file(
      std::string(RBCSIM_SOURCE_DIR) + "/share/reference/mills2004_stretch.csv"));
  const cases::ContactSettings contact{.rigid = GetParam().rigid_contact};
  const auto cell = cases::prepare_stretch_cell(cases::testing::evans_fung_discocyte(4), contact);
  MembraneParameters parameters;
  parameters.forces = GetParam().terms;
  const rbcsim::membrane::MembraneModel model(cell.mesh, parameters);
  cases::StretchSettings settings;
  settings.contact = contact;
  for (const auto& measured : reference) settings.forces_pN.push_back(measured.force_pN);

  const auto start = std::chrono::steady_clock::now();
  const auto run = cases::run_stretch(model, cell, settings, {});
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(run.ok()) << run.failure;
  std::printf("terms:");
  for (const auto& term : parameters.forces) std::printf(" %s", term.c_str());
  std::printf(", %s contact patches", contact.rigid ? "rigid" : "free");
  std::printf("\n force_pN  axial_um (Mills)   transverse_um (Mills)  iterations\n");
  for (std::size_t i = 0; i < run.points.size(); ++i) {
    const auto& p = run.points[i];
    std::printf("%9.3f  %7.3f (%6.3f)   %7.3f (%6.3f)        %6zu\n", p.force_pN, p.axial_um,
                reference[i].axial.mean_um, p.transverse_um, reference[i].transverse.mean_um,
                p.iterations);
  }
  char run_summary[32];
  std::snprintf(run_summary, sizeof run_summary, "wall time %.1f s", wall_s);
  cases::testing::expect_and_print_mills_comparison(run.points, reference, run_summary);
}

const std::vector<std::string> kSixTerms{
    "link", "bend", "area", "volume", "area_difference", "total_curvature"};
const std::vector<std::string> kFourTerms{"link", "bend", "area", "volume"};

INSTANTIATE_TEST_SUITE_P(ValidateTerms, ValidateStretch,
                         ::testing::Values(StretchVariant{kSixTerms}, StretchVariant{kFourTerms},
                                           StretchVariant{kSixTerms, true}),
                         [](const ::testing::TestParamInfo<StretchVariant>& variant) {
                           return variant_name(variant.param);
                         });

}  // namespace
