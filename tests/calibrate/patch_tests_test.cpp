// The patch tests of `rbcsim calibrate` against closed-form answers: the harmonic spring network
// (reference/membrane_constants.csv), the area term's own contribution, the dihedral spring of
// the two-triangle patch, the uniform curvature mode of a cell, and fits that recover known k.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cases/bending_patches.hpp"
#include "cases/calibration.hpp"
#include "cases/hexagonal_patch.hpp"
#include "common/errors.hpp"
#include "membrane/reference_state.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/topology.hpp"

#include "support/relative_difference.hpp"

namespace {

using rbcsim::cases::measure_hexagonal_patch;
using rbcsim::membrane::MembraneParameters;

constexpr double kStrain = 1e-3;
constexpr double kAngleRad = 1e-3;

using rbcsim::testing::relative_difference;

// k_s = F / dL of one link at small strain: (k_l kBT / p)(1 + 1/tau_l^2) / a (Eq. 6).
double link_spring_pN_per_um(const MembraneParameters& parameters, double edge_um) {
  return parameters.k_link_kBT * parameters.thermal_energy_pN_um /
         parameters.persistence_length_um *
         (1.0 + 1.0 / (parameters.tau_link * parameters.tau_link)) / edge_um;
}

// membrane_constants.csv, harmonic_network_*: a triangular lattice of springs k has
// mu = sqrt(3) k / 4, K = sqrt(3) k / 2, Y = 2 k / sqrt(3), nu = 1/3.
TEST(HexagonalPatch, LinkNetworkMatchesTheSpringLatticeRelations) {
  for (const double edge_um : {0.25, 0.31}) {
    MembraneParameters parameters;
    parameters.k_area_kBT = 0.0;
    const auto patch = measure_hexagonal_patch(parameters, edge_um, kStrain);
    const double spring = link_spring_pN_per_um(parameters, edge_um);
    EXPECT_LT(relative_difference(patch.network.shear_uN_per_m, std::sqrt(3.0) / 4.0 * spring),
              0.01);
    EXPECT_LT(relative_difference(patch.network.area_uN_per_m, std::sqrt(3.0) / 2.0 * spring),
              0.01);
    EXPECT_LT(relative_difference(patch.network.young_uN_per_m, 2.0 / std::sqrt(3.0) * spring),
              0.01);
    EXPECT_LT(relative_difference(patch.network.poisson_ratio, 1.0 / 3.0), 0.01);
    // The isolated patch counts its 6 rim links whole: 12 links where the tiling has 9.
    EXPECT_LT(relative_difference(patch.isolated.shear_uN_per_m,
                                  4.0 / 3.0 * patch.network.shear_uN_per_m),
              1e-6);
    // The free centre needs no load at the affine position (point symmetry).
    EXPECT_LT(patch.largest_centre_force_pN, 1e-9 * spring * edge_um);
  }
}

// The area term's energy per triangle K_t energy(d) with K_t = (k_a kBT / L0) 6 A0 / P0 adds
// K_t (1 + 1/tau_a^2) / A0 = 2 k_a kBT (1 + 1/tau_a^2) / (L0 a) to K, and nothing to mu.
TEST(HexagonalPatch, AreaTermAddsItsOwnAnalyticValueToKOnly) {
  MembraneParameters parameters;
  parameters.k_link_kBT = 0.0;
  const double edge_um = 0.27;
  const auto patch = measure_hexagonal_patch(parameters, edge_um, kStrain);
  const double tau = parameters.tau_area;
  const double expected = 2.0 * parameters.k_area_kBT * parameters.thermal_energy_pN_um *
                          (1.0 + 1.0 / (tau * tau)) / (parameters.force_length_scale_um * edge_um);
  EXPECT_LT(relative_difference(patch.network.area_uN_per_m, expected), 0.01);
  EXPECT_LT(std::abs(patch.network.shear_uN_per_m), 1e-6 * expected);
  // Triangles are not shared between patches: both readings agree.
  EXPECT_LT(relative_difference(patch.isolated.area_uN_per_m, expected), 0.01);
}

TEST(HexagonalPatch, MeasuredUnitStiffnessMatchesTheClosedForm) {
  const MembraneParameters parameters;
  for (const double edge_um : {0.25, 0.22}) {
    const auto measured = rbcsim::cases::measure_patch_stiffness(parameters, edge_um, kStrain);
    const auto analytic = rbcsim::cases::analytic_patch_stiffness(parameters, edge_um);
    EXPECT_LT(relative_difference(measured.link_shear_uN_per_m, analytic.link_shear_uN_per_m),
              0.01);
    EXPECT_LT(relative_difference(measured.link_area_uN_per_m, analytic.link_area_uN_per_m), 0.01);
    EXPECT_LT(
        relative_difference(measured.area_term_area_uN_per_m, analytic.area_term_area_uN_per_m),
        0.01);
  }
}

// Two equilateral triangles of edge a = L0: the wing moment per rad is (sqrt 3 / 2) k_b kBT
// (1 + 1/tau_b^2) in both distributions, and with dx = a / sqrt 3, D = k_b kBT (1 + 1/tau_b^2) / 2.
// At another edge the `gradient` D stays, the `paper` one scales with a / L0 (its push has the
// fixed scale k_b kBT / L0, its arm is the wing's height).
TEST(TwoTrianglePatch, BendingStiffnessIsTheDihedralSpringsOwn) {
  for (const std::string distribution : {"gradient", "paper"}) {
    MembraneParameters parameters;
    parameters.distribution = distribution;
    const double edge_um = parameters.force_length_scale_um;
    const auto patch = rbcsim::cases::measure_two_triangle_patch(parameters, edge_um, kAngleRad);
    const double tau = parameters.tau_bend_rad;
    const double kBT = parameters.thermal_energy_pN_um;
    const double factor = 1 + 1 / (tau * tau);
    EXPECT_LT(relative_difference(patch.moment_per_angle_pN_um,
                                  std::sqrt(3.0) / 2.0 * parameters.k_bend_kBT * kBT * factor),
              0.01)
        << distribution;
    EXPECT_NEAR(patch.hinge_distance_um, edge_um / std::sqrt(3.0), 1e-12);
    const double expected_J = parameters.k_bend_kBT * kBT * 1e-18 * factor / 2.0;
    EXPECT_LT(relative_difference(patch.bending_modulus_J, expected_J), 0.01) << distribution;

    const double other_edge_um = 0.8 * edge_um;
    const auto other =
        rbcsim::cases::measure_two_triangle_patch(parameters, other_edge_um, kAngleRad);
    const double scale = distribution == "paper" ? 0.8 : 1.0;
    EXPECT_LT(relative_difference(other.bending_modulus_J, scale * expected_J), 0.01)
        << distribution;
    EXPECT_LT(relative_difference(other.bending_modulus_J,
                                  rbcsim::cases::analytic_two_triangle_bending_modulus_J(
                                      parameters, other_edge_um)),
              0.01)
        << distribution;
  }
}

rbcsim::mesh::TriangleMesh small_discocyte() { return rbcsim::mesh::generate_cell("discocyte", 2); }

// Every dihedral angle + delta: the bending energy is N_edges (sqrt 3 / 2) k_b kBT energy(delta),
// E'' = N_edges (sqrt 3 / 2) k_b kBT (1 + 1/tau_b^2); the area difference changes by
// sum l delta / 2, so E''_ad = sqrt 3 k_ad kBT (1 + 1/tau_ad^2) (sum l / 2)^2 / (L0 |S0|), and the
// total curvature likewise with sum l sign(theta0) and C0 / 2 D0.
TEST(UniformCurvatureMode, EnergiesMatchTheTermsClosedForms) {
  const auto cell = small_discocyte();
  MembraneParameters parameters;
  const auto stiffness =
      rbcsim::cases::measure_uniform_curvature_stiffness(cell, parameters, kAngleRad);

  const auto topology = rbcsim::mesh::MeshTopology::build(cell);
  const auto rest =
      rbcsim::membrane::capture_reference_state(cell.positions_um, cell.triangles, topology);
  double length_um = 0.0;
  double signed_length_um = 0.0;
  for (std::size_t e = 0; e < topology.edge_count(); ++e) {
    length_um += rest.edge_lengths_um[e];
    signed_length_um += std::copysign(rest.edge_lengths_um[e], rest.dihedral_angles_rad[e]);
  }
  const double kBT = parameters.thermal_energy_pN_um;
  const double L0 = parameters.force_length_scale_um;
  const auto factor = [](double tau) { return 1.0 + 1.0 / (tau * tau); };
  const double bend = static_cast<double>(topology.edge_count()) * std::sqrt(3.0) / 2.0 *
                      parameters.k_bend_kBT * kBT * factor(parameters.tau_bend_rad);
  const double area_difference = std::sqrt(3.0) * parameters.k_area_difference_kBT * kBT *
                                 factor(parameters.tau_area_difference) *
                                 std::pow(length_um / 2.0, 2) /
                                 (L0 * std::abs(rest.signed_curvature_sum_um));
  const double total_curvature = std::sqrt(3.0) * parameters.k_total_curvature_kBT * kBT *
                                 factor(parameters.tau_total_curvature) *
                                 std::pow(signed_length_um / 2.0, 2) /
                                 (L0 * rest.absolute_curvature_sum_um);
  EXPECT_LT(relative_difference(stiffness.bend_pN_um, bend), 1e-4);
  EXPECT_LT(relative_difference(stiffness.area_difference_pN_um, area_difference), 0.01);
  EXPECT_LT(relative_difference(stiffness.total_curvature_pN_um, total_curvature), 0.01);
}

// A cell-level term switched off in membrane.forces adds nothing; with both off there is nothing
// to fit.
TEST(UniformCurvatureMode, SwitchedOffTermsAddNothing) {
  const auto cell = small_discocyte();
  MembraneParameters parameters;
  const auto all = rbcsim::cases::measure_uniform_curvature_stiffness(cell, parameters, kAngleRad);
  parameters.forces = {"link", "bend", "area", "volume", "total_curvature"};
  const auto without =
      rbcsim::cases::measure_uniform_curvature_stiffness(cell, parameters, kAngleRad);
  EXPECT_EQ(without.area_difference_pN_um, 0.0);
  EXPECT_EQ(without.total_curvature_pN_um, all.total_curvature_pN_um);
  EXPECT_EQ(without.bend_pN_um, all.bend_pN_um);
  parameters.forces = {"link", "bend", "area", "volume"};
  EXPECT_THROW(rbcsim::cases::run_calibration(cell, parameters, {}), rbcsim::InputError);
}

// Targets made from chosen k: the fits must give those k back.
TEST(CalibrationFits, RecoverKnownStiffnesses) {
  const auto cell = small_discocyte();
  MembraneParameters chosen;
  chosen.k_link_kBT = 9.3;
  chosen.k_area_kBT = 2.7;
  chosen.k_bend_kBT = 31.0;
  chosen.k_area_difference_kBT = 12.0;
  chosen.k_total_curvature_kBT = 4.0;
  rbcsim::cases::CalibrationSettings settings;
  settings.fits = {};
  const auto truth = rbcsim::cases::run_calibration(cell, chosen, settings);
  settings.fits = rbcsim::cases::CalibrationSettings{}.fits;  // the patch tests' (stretch_fit_test)

  settings.targets.shear_uN_per_m = truth.hexagonal.network.shear_uN_per_m;
  settings.targets.area_uN_per_m = truth.hexagonal.network.area_uN_per_m;
  settings.targets.bending_modulus_J = truth.two_triangle.bending_modulus_J;
  settings.targets.overall_bending_modulus_J = truth.overall_bending_modulus_J;
  const auto fitted = rbcsim::cases::run_calibration(cell, MembraneParameters{}, settings).fitted;
  EXPECT_LT(relative_difference(fitted.k_link_kBT, chosen.k_link_kBT), 0.01);
  EXPECT_LT(relative_difference(fitted.k_area_kBT, chosen.k_area_kBT), 0.01);
  EXPECT_LT(relative_difference(fitted.k_bend_kBT, chosen.k_bend_kBT), 0.01);
  EXPECT_LT(relative_difference(fitted.k_area_difference_kBT, chosen.k_area_difference_kBT), 0.01);
  EXPECT_LT(relative_difference(fitted.k_total_curvature_kBT, chosen.k_total_curvature_kBT), 0.01);

  // The same in-plane targets as E_s and Poisson.
  settings.fits = {"link_area"};
  settings.targets.moduli = "young-poisson";
  settings.targets.young_uN_per_m = truth.hexagonal.network.young_uN_per_m;
  settings.targets.poisson_ratio = truth.hexagonal.network.poisson_ratio;
  const auto young = rbcsim::cases::run_calibration(cell, MembraneParameters{}, settings);
  EXPECT_LT(relative_difference(young.fitted.k_link_kBT, chosen.k_link_kBT), 0.01);
  EXPECT_LT(relative_difference(young.fitted.k_area_kBT, chosen.k_area_kBT), 0.01);
  ASSERT_TRUE(young.link_area.has_value());
  EXPECT_LT(young.link_area->relative_residual, 1e-3);
  EXPECT_FALSE(young.bend.has_value());
}

// K below the links' own 2 mu (k_area < 0), or an overall modulus below the bending term's D,
// cannot be reached: an input error naming the option.
TEST(CalibrationFits, UnreachableTargetsAreInputErrors) {
  const auto cell = small_discocyte();
  rbcsim::cases::CalibrationSettings settings;
  settings.targets.area_uN_per_m = settings.targets.shear_uN_per_m;
  try {
    rbcsim::cases::run_calibration(cell, MembraneParameters{}, settings);
    FAIL() << "no error";
  } catch (const rbcsim::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("calibrate.target.area_modulus_uN_per_m"),
              std::string::npos)
        << error.what();
  }
  settings = {};
  settings.targets.overall_bending_modulus_J = 0.5 * settings.targets.bending_modulus_J;
  EXPECT_THROW(rbcsim::cases::run_calibration(cell, MembraneParameters{}, settings),
               rbcsim::InputError);
  settings = {};
  settings.fits = {"bend", "nonsense"};
  EXPECT_THROW(rbcsim::cases::run_calibration(cell, MembraneParameters{}, settings),
               rbcsim::InputError);
}

}  // namespace
