// The optimised membrane kernel against the reference kernel (docs/architecture.md: every
// optimised kernel is tested for equivalence with the plain one): every subset of the six terms,
// both distributions, two random deformations of the test shapes. Also what the optimised kernel
// promises beyond equal forces: the two levels of detail, the same limit errors, an atan2 as
// accurate as the library's, and the benchmark helper.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "membrane/benchmark.hpp"
#include "membrane/hinge.hpp"
#include "membrane/membrane_kernel.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/simd_math.hpp"
#include "test_shapes.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::membrane::ForceDetail;
using rbcsim::membrane::MembraneForces;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
namespace shapes = rbcsim::membrane_test;

// Bit i: the i-th term the optimised kernel fuses (the paper's six, total_area, helfrich and
// local_area).
const unsigned kAllTerms = (1u << rbcsim::membrane::fused_force_term_names().size()) - 1u;

struct EquivalenceShape {
  shapes::ShapeRecipe recipe;  // built in the test, not at start-up (test_shapes.hpp)
  bool every_subset;  // every subset of the fused terms, or only each term alone and all of them
};

// Levels 0 and 2 have a last block of elements shorter than the others (30 edges; 480 edges and
// 80 triangles against blocks of 64), levels 3 and 4 only full blocks.
const std::vector<EquivalenceShape>& equivalence_shapes() {
  static const std::vector<EquivalenceShape> all = [] {
    std::vector<EquivalenceShape> list = {
        {{"ellipsoid0", [] { return shapes::ellipsoid(0, Vec3(4.0, 3.0, 2.0)); }}, true},
        {{"ellipsoid2", [] { return shapes::ellipsoid(2, Vec3(4.0, 3.0, 2.0)); }}, true}};
    for (const auto& recipe : shapes::property_test_recipes()) {
      list.push_back({recipe, recipe.name.back() == '3'});
    }
    return list;
  }();
  return all;
}

std::vector<std::string> term_subset(unsigned mask) {
  const auto all = rbcsim::membrane::fused_force_term_names();
  std::vector<std::string> subset;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if ((mask >> i) & 1u) subset.push_back(all[i]);
  }
  return subset;
}

std::vector<unsigned> subsets_of(const EquivalenceShape& shape) {
  std::vector<unsigned> masks;
  if (shape.every_subset) {
    for (unsigned mask = 0; mask <= kAllTerms; ++mask) masks.push_back(mask);
  } else {
    for (unsigned bit = 0; (1u << bit) <= kAllTerms; ++bit) masks.push_back(1u << bit);
    masks.push_back(kAllTerms);
  }
  return masks;
}

MembraneParameters parameters_for(unsigned mask, const std::string& distribution,
                                  std::string_view kernel) {
  MembraneParameters parameters;
  parameters.forces = term_subset(mask);
  parameters.distribution = distribution;
  parameters.kernel = std::string(kernel);
  parameters.vertex_force_cap_pN = INFINITY;  // the raw forces
  return parameters;
}

MembraneForces compute_forces(const MembraneModel& model, const std::vector<Vec3>& positions_um,
                              ForceDetail detail = ForceDetail::per_term) {
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  model.compute(positions_um, workspace, forces, detail);
  return forces;
}

double max_norm(const std::vector<Vec3>& vectors) {
  double largest = 0.0;
  for (const auto& v : vectors) largest = std::max(largest, v.norm());
  return largest;
}

double max_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  EXPECT_EQ(a.size(), b.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, (a[i] - b[i]).norm());
  return largest;
}

// Next to the property tests' small deformation, a large one: 5 % stretch and vertex noise of 6 %
// of the mean edge, which drives every law well into its nonlinear range (still below tau).
std::vector<Vec3> large_deformation(const shapes::TriangleMesh& mesh, std::uint32_t seed) {
  std::vector<Vec3> positions = mesh.positions_um;
  for (auto& p : positions) p = p.cwiseProduct(Vec3(1.05, 0.98, 0.97));
  return shapes::with_noise(std::move(positions), 0.06 * shapes::mean_edge_length_um(mesh), seed);
}

// The scales the differences are measured against, from the reference with all six terms at the
// same deformation: one term's forces can be far below round-off of the others (the `paper`
// area-difference force is zero up to round-off), so "relative" means relative to the forces
// and the energy the membrane carries there.
struct Scales {
  double force_pN = 0.0;      // largest vertex force of any term
  double energy_pN_um = 0.0;  // total energy
  // A cell term's force and energy change per unit of its deviation d (largest over the cell
  // terms): d carries an absolute round-off (kDeviationTolerance below), so they carry that times
  // these. It matters for a stiff term (total_area at the bilayer's modulus: a round-off of 1e-15
  // in d is 3e-11 pN), not for the paper's soft ones.
  double force_per_deviation_pN = 0.0;
  double energy_per_deviation_pN_um = 0.0;
};

bool is_cell_term(const std::string& name) {
  return name == "volume" || name == "area_difference" || name == "total_curvature" ||
         name == "total_area";
}

Scales scales_at(const shapes::TriangleMesh& mesh, const std::string& distribution,
                 const std::vector<Vec3>& positions_um) {
  const auto forces = compute_forces(
      MembraneModel(mesh, parameters_for(kAllTerms, distribution, "reference")), positions_um);
  Scales scales;
  for (const auto& term : forces.terms) {
    scales.force_pN = std::max(scales.force_pN, max_norm(term.forces_pN));
    if (is_cell_term(term.name) && term.max_abs_deviation > 0.0) {
      // F is about linear in d here and E quadratic, so dF/dd ~ F/d and dE/dd ~ 2E/d.
      scales.force_per_deviation_pN = std::max(scales.force_per_deviation_pN,
                                               max_norm(term.forces_pN) / term.max_abs_deviation);
      scales.energy_per_deviation_pN_um =
          std::max(scales.energy_per_deviation_pN_um,
                   2.0 * std::abs(term.energy_pN_um) / term.max_abs_deviation);
    }
  }
  scales.energy_pN_um = forces.total_energy_pN_um();
  return scales;
}

// Round-off of a deviation: d of a cell term is (S - S0)/|S0| with S a sum over thousands of
// elements summed in another order (fixed blocks) by the optimised kernel, so its round-off is
// absolute, about n eps |terms| / |S0| (measured: below 5e-15), not relative to a small d.
constexpr double kDeviationTolerance = 1e-13;
// Forces and energies: 1e-12 of the scales above (measured: forces below 1e-13, energies below
// 2e-13, the volume energy's, which carries the absolute round-off of d_V squared).
constexpr double kRelativeTolerance = 1e-12;

void expect_equivalent(const MembraneForces& expected, const MembraneForces& actual,
                       const Scales& scales, const std::string& where) {
  const double force_tolerance_pN =
      kRelativeTolerance * scales.force_pN + kDeviationTolerance * scales.force_per_deviation_pN;
  const double energy_tolerance_pN_um = kRelativeTolerance * scales.energy_pN_um +
                                        kDeviationTolerance * scales.energy_per_deviation_pN_um;
  EXPECT_LE(max_difference(expected.total_pN, actual.total_pN), force_tolerance_pN) << where;
  ASSERT_EQ(expected.terms.size(), actual.terms.size()) << where;
  for (std::size_t i = 0; i < expected.terms.size(); ++i) {
    const auto& e = expected.terms[i];
    const auto& a = actual.terms[i];
    ASSERT_EQ(e.name, a.name);
    EXPECT_LE(max_difference(e.forces_pN, a.forces_pN), force_tolerance_pN)
        << where << " " << e.name;
    EXPECT_NEAR(a.energy_pN_um, e.energy_pN_um, energy_tolerance_pN_um) << where << " " << e.name;
    EXPECT_NEAR(a.max_abs_deviation, e.max_abs_deviation, kDeviationTolerance)
        << where << " " << e.name;
  }
  EXPECT_NEAR(actual.cell.volume, expected.cell.volume, kDeviationTolerance) << where;
  EXPECT_NEAR(actual.cell.total_area, expected.cell.total_area, kDeviationTolerance) << where;
  EXPECT_NEAR(actual.cell.area_difference, expected.cell.area_difference, kDeviationTolerance)
      << where;
  EXPECT_NEAR(actual.cell.total_curvature, expected.cell.total_curvature, kDeviationTolerance)
      << where;
  EXPECT_EQ(actual.capped_vertex_count, expected.capped_vertex_count) << where;
}

using ShapeAndDistribution = std::tuple<std::size_t, std::string>;  // shape, distribution

class KernelEquivalence : public ::testing::TestWithParam<ShapeAndDistribution> {};

TEST_P(KernelEquivalence, EveryTermSubsetAgreesWithTheReference) {
  const auto& [shape_index, distribution] = GetParam();
  const auto& shape = equivalence_shapes()[shape_index];
  const auto mesh = shape.recipe.build();
  const auto seed = 2000u + static_cast<std::uint32_t>(shape_index);
  const std::vector<std::vector<Vec3>> deformations = {shapes::small_deformation(mesh, seed),
                                                       large_deformation(mesh, seed)};
  std::vector<Scales> scales;
  for (const auto& positions : deformations) {
    scales.push_back(scales_at(mesh, distribution, positions));
    ASSERT_GT(scales.back().force_pN, 1e-3);  // the comparison is not vacuous
    ASSERT_GT(scales.back().energy_pN_um, 1e-6);
  }
  for (unsigned mask : subsets_of(shape)) {
    const MembraneModel reference(mesh, parameters_for(mask, distribution, "reference"));
    const MembraneModel optimised(mesh, parameters_for(mask, distribution, "optimised"));
    for (std::size_t d = 0; d < deformations.size(); ++d) {
      expect_equivalent(compute_forces(reference, deformations[d]),
                        compute_forces(optimised, deformations[d]), scales[d],
                        "term mask " + std::to_string(mask) + ", deformation " + std::to_string(d));
    }
  }
}

std::string shape_and_distribution_name(
    const ::testing::TestParamInfo<ShapeAndDistribution>& info) {
  return equivalence_shapes()[std::get<0>(info.param)].recipe.name + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(
    AllShapes, KernelEquivalence,
    ::testing::Combine(::testing::Range<std::size_t>(0, equivalence_shapes().size()),
                       ::testing::Values("paper", "gradient")),
    shape_and_distribution_name);

// The force cap acts on the same totals: the same vertices are clamped, to the same forces.
TEST(KernelEquivalence, TheForceCapClampsTheSameVertices) {
  const auto mesh = shapes::discocyte(3);
  const auto positions = large_deformation(mesh, 5);
  auto parameters = parameters_for(kAllTerms, "gradient", "reference");
  parameters.vertex_force_cap_pN = 0.05;
  const auto expected = compute_forces(MembraneModel(mesh, parameters), positions);
  parameters.kernel = "optimised";
  const auto actual = compute_forces(MembraneModel(mesh, parameters), positions);
  EXPECT_GT(expected.capped_vertex_count, 0u);
  EXPECT_EQ(actual.capped_vertex_count, expected.capped_vertex_count);
  EXPECT_LE(max_difference(expected.total_pN, actual.total_pN),
            kRelativeTolerance * parameters.vertex_force_cap_pN);
}

// ForceDetail::totals gives the same totals, bit for bit, and marks the detail it skipped; a
// per-term evaluation afterwards fills the arrays again.
TEST(ForceDetail, TotalsAreTheSameBitsAndTheSkippedDetailIsMarked) {
  const auto mesh = shapes::discocyte(3);
  const auto positions = shapes::small_deformation(mesh, 31);
  for (const auto& kernel : rbcsim::membrane::membrane_kernel_table()) {
    const MembraneModel model(mesh, parameters_for(kAllTerms, "gradient", kernel.name));
    auto workspace = model.make_workspace();
    auto forces = model.make_forces();
    model.compute(positions, workspace, forces, ForceDetail::per_term);
    const auto per_term = forces;
    model.compute(positions, workspace, forces, ForceDetail::totals);
    EXPECT_EQ(forces.total_pN, per_term.total_pN) << kernel.name;
    EXPECT_TRUE(std::isnan(forces.total_energy_pN_um())) << kernel.name;
    for (std::size_t i = 0; i < forces.terms.size(); ++i) {
      EXPECT_TRUE(forces.terms[i].forces_pN.empty()) << kernel.name;
      EXPECT_TRUE(std::isnan(forces.terms[i].energy_pN_um)) << kernel.name;
      EXPECT_EQ(forces.terms[i].max_abs_deviation, per_term.terms[i].max_abs_deviation);
    }
    model.compute(positions, workspace, forces, ForceDetail::per_term);
    for (std::size_t i = 0; i < forces.terms.size(); ++i) {
      EXPECT_EQ(forces.terms[i].forces_pN, per_term.terms[i].forces_pN) << kernel.name;
      EXPECT_EQ(forces.terms[i].energy_pN_um, per_term.terms[i].energy_pN_um) << kernel.name;
    }
  }
}

// A deviation at its limit: both kernels throw the same RuntimeFailure (term and first element),
// checking the terms in registry order.
TEST(KernelEquivalence, LimitErrorsNameTheSameTermAndElement) {
  const auto mesh = shapes::sphere(2, 3.0);
  const auto topology = rbcsim::mesh::MeshTopology::build(mesh);
  const auto captured =
      rbcsim::membrane::capture_reference_state(mesh.positions_um, mesh.triangles, topology);
  struct Violation {
    std::string expected_text;
    void (*edit)(rbcsim::membrane::ReferenceState&);
  };
  const std::vector<Violation> violations = {
      {"'link': edge 9 ", [](auto& r) { r.edge_lengths_um[9] /= 5.0; }},         // d = 4 > 3
      {"'area': triangle 7 ", [](auto& r) { r.triangle_areas_um2[7] *= 2.0; }},  // d = -0.5
      {"'volume': the cell", [](auto& r) { r.volume_um3 *= 1.2; }},              // d = -0.17
      {"'area_difference': the cell", [](auto& r) { r.signed_curvature_sum_um /= 3.0; }},  // 2
      {"'total_curvature': the cell", [](auto& r) { r.absolute_curvature_sum_um /= 5.0; }},
      // Two at once: the first in registry order (link before area) is reported.
      {"'link': edge 3 ", [](auto& r) {
         r.triangle_areas_um2[2] *= 2.0;
         r.edge_lengths_um[3] /= 5.0;
       }}};
  for (const auto& violation : violations) {
    auto reference = captured;
    violation.edit(reference);
    std::vector<std::string> messages;
    for (const auto& kernel : rbcsim::membrane::membrane_kernel_table()) {
      const MembraneModel model(mesh, reference,
                                parameters_for(kAllTerms, "gradient", kernel.name));
      try {
        compute_forces(model, mesh.positions_um, ForceDetail::totals);
        ADD_FAILURE() << kernel.name << ": no error for " << violation.expected_text;
      } catch (const rbcsim::RuntimeFailure& error) {
        messages.emplace_back(error.what());
      }
    }
    ASSERT_EQ(messages.size(), 2u);
    EXPECT_EQ(messages[0], messages[1]);
    EXPECT_NE(messages[0].find(violation.expected_text), std::string::npos) << messages[0];
  }
}

// Every registered distribution works with every registered kernel.
TEST(MembraneKernelTable, EveryKernelTakesEveryDistribution) {
  const auto mesh = shapes::sphere(1, 3.0);
  for (const auto& kernel : rbcsim::membrane::membrane_kernel_table()) {
    for (const auto& distribution : rbcsim::membrane::hinge_distribution_table()) {
      EXPECT_NO_THROW(MembraneModel(
          mesh, parameters_for(kAllTerms, std::string(distribution.name), kernel.name)));
    }
  }
}

// The optimised kernel's branch-free atan2 against the library's, in every octant, near the axes
// and the diagonals, and at the points where the octant logic switches.
TEST(SimdMath, Atan2IsWithinFourUlpOfTheLibrary) {
  std::mt19937_64 generator(17);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<std::pair<double, double>> points = {
      {0.0, 1.0},    {1.0, 0.0},    {0.0, -1.0}, {-1.0, 0.0},  {-0.0, -1.0},
      {1.0, 1.0},    {-1.0, 1.0},   {1.0, -1.0}, {-1.0, -1.0}, {std::numbers::sqrt2 - 1.0, 1.0},
      {1e-300, 1.0}, {1.0, 1e-300}, {3e-4, -2.0}};
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::pow(10.0, 6.0 * uniform(generator));
    const double y = scale * uniform(generator);  // not drawn in emplace_back's arguments, whose
    const double x = scale * uniform(generator);  // order the compiler picks
    points.emplace_back(y, x);
  }
  for (const auto& [y, x] : points) {
    const double expected = std::atan2(y, x);
    const double ulp = std::nextafter(std::abs(expected), INFINITY) - std::abs(expected);
    EXPECT_LE(std::abs(rbcsim::membrane::simd::atan2(y, x) - expected), 4.0 * ulp)
        << "atan2(" << y << ", " << x << ")";
  }
  EXPECT_EQ(rbcsim::membrane::simd::atan2(0.0, 0.0), 0.0);
}

TEST(Benchmark, MeasuresBothKernelsAndRejectsBadArguments) {
  for (const auto& kernel : rbcsim::membrane::membrane_kernel_table()) {
    const double microseconds = rbcsim::membrane::measure_membrane_force_us(2, 1, kernel.name);
    EXPECT_TRUE(std::isfinite(microseconds) && microseconds > 0.0) << kernel.name;
  }
  EXPECT_THROW(rbcsim::membrane::measure_membrane_force_us(2, 1, "fastest"), rbcsim::InputError);
  EXPECT_THROW(rbcsim::membrane::measure_membrane_force_us(2, 0, "optimised"), rbcsim::InputError);
  EXPECT_THROW(rbcsim::membrane::measure_membrane_force_us(8, 1, "optimised"), rbcsim::InputError);
}

}  // namespace
