// The calibrate experiment (paper §2.3; docs/commands/calibrate.md): measures what the membrane's
// k parameters mean on the patch tests and fits them to target moduli.
//
//   auto calibration = run_calibration(cell_mesh, membrane_parameters, settings);
//   calibrate_result_section(calibration);    // result.json's "calibrate" object
//   fitted_parameters_document(calibration);  // parameters.json, a config --config accepts
//
// Measurements (always, with the configured k): the hexagonal patch (hexagonal_patch.hpp: E_s,
// mu, K, Poisson), the two-triangle patch (bending_patches.hpp: D) and the cell's overall bending
// modulus with the area-difference and total-curvature terms. Fits, chosen by name from one table
// (settings.fits), run in the table's order (the curvature fit uses the fitted k_b):
//   link_area         k_l, k_a to target mu and K (or E_s and Poisson): a 2x2 linear solve,
//                     since the small-strain moduli are linear in k;
//   bend              k_b to a target D: linear;
//   curvature_terms   k_ad, k_c (at a fixed ratio k_ad / k_c) to a target overall modulus: linear.
//   stretch           k_l to a measured optical-tweezers curve (stretch_fit.hpp: Mills et al.
//                     2004, quasi-static stretches, minutes at the paper's resolution); not run
//                     unless asked for. It replaces a k_l fitted by link_area.
// Each fit is then checked by measuring again with the fitted k: the residual is reported (for
// the stretch fit, the curve's deviations from the measurement and the moduli of its k_l).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cases/bending_patches.hpp"
#include "cases/hexagonal_patch.hpp"
#include "cases/stretch_fit.hpp"
#include "membrane/parameters.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

// The paper's values (§2.3, Table 2): the patch results and the k that gave them.
struct PaperCalibration {
  static constexpr double young_uN_per_m = 29.85;
  static constexpr double shear_uN_per_m = 10.15;
  static constexpr double area_uN_per_m = 28.2;
  static constexpr double poisson_ratio = 0.33;
  static constexpr double k_link_kBT = 7.0;
  static constexpr double k_area_kBT = 5.0;
  static constexpr double bending_modulus_J = 2e-19;  // Evans (1983), "equal to" k_b = 50 kBT
  static constexpr double k_bend_kBT = 50.0;
  static constexpr double overall_bending_modulus_J = 2.5e-19;
  static constexpr double k_area_difference_kBT = 300.0;
  static constexpr double k_total_curvature_kBT = 100.0;
};

struct CalibrationTargets {
  // Which pair of in-plane targets the link_area fit uses: "shear-area" (mu, K) or
  // "young-poisson" (E_s, nu, converted to mu = E/(2(1 + nu)), K = E/(2(1 - nu))).
  std::string moduli = "shear-area";
  double shear_uN_per_m = PaperCalibration::shear_uN_per_m;
  double area_uN_per_m = PaperCalibration::area_uN_per_m;
  double young_uN_per_m = PaperCalibration::young_uN_per_m;
  double poisson_ratio = PaperCalibration::poisson_ratio;
  double bending_modulus_J = PaperCalibration::bending_modulus_J;
  double overall_bending_modulus_J = PaperCalibration::overall_bending_modulus_J;
};

struct CalibrationSettings {
  // The patch-test fits, fractions of a second; the stretch fit (minutes) only when asked for.
  std::vector<std::string> fits = {"link_area", "bend", "curvature_terms"};
  // The patches' rest edge a: "mesh-mean-edge" (the cell mesh's mean edge: the k are
  // mesh-dependent, so calibrate for the mesh that will run) or "force-length-scale" (Table 2's
  // L0, membrane.force_length_scale_um).
  std::string patch_edge = "mesh-mean-edge";
  double strain = 1e-3;     // hexagonal patch strain amplitude
  double angle_rad = 1e-3;  // fold of the two-triangle patch, uniform perturbation of the cell
  double area_difference_per_total_curvature = 3.0;  // k_ad / k_c (the paper's 300 / 100)
  CalibrationTargets targets;
  StretchFitSettings stretch_fit;  // the stretch fit's set-up and reference curve
};

std::vector<std::string> calibration_fit_names();
std::vector<std::string> patch_edge_rule_names();
std::vector<std::string> target_moduli_names();

struct LinkAreaFit {
  double target_shear_uN_per_m = 0.0;
  double target_area_uN_per_m = 0.0;
  double k_link_kBT = 0.0;
  double k_area_kBT = 0.0;
  MembraneModuli achieved;         // measured again with the fitted k
  double relative_residual = 0.0;  // largest relative error of mu and K
};

struct StiffnessFit {
  double target_J = 0.0;
  double achieved_J = 0.0;  // measured again with the fitted k
  double relative_residual = 0.0;
};

struct StretchCurveFit {
  StretchFit curve;         // the fitted k_l, its curve against the reference, every curve run
  MembraneModuli achieved;  // the hexagonal patch's moduli with the fitted k_l
};

struct Calibration {
  CalibrationSettings settings;
  double patch_edge_um = 0.0;
  membrane::MembraneParameters configured;
  HexagonalPatchMeasurement hexagonal;       // with the configured k_l, k_a
  PatchStiffness unit_patch;                 // measured, per kBT
  PatchStiffness analytic_patch;             // closed form, per kBT
  TwoTrianglePatchMeasurement two_triangle;  // with the configured k_b
  double analytic_bending_modulus_J = 0.0;
  double unit_bending_modulus_J = 0.0;       // D at k_b = 1 kBT
  UniformCurvatureStiffness unit_curvature;  // at k_b = k_ad = k_c = 1 kBT
  double overall_bending_modulus_J = 0.0;    // with the configured k_b, k_ad, k_c
  std::optional<LinkAreaFit> link_area;
  std::optional<StiffnessFit> bend;
  std::optional<StiffnessFit> curvature_terms;
  std::optional<StretchCurveFit> stretch;
  membrane::MembraneParameters fitted;  // the configured parameters with the fitted k
};

// Throws InputError for an unknown fit, patch-edge rule or target kind, and for targets no
// non-negative k reaches (naming the calibrate.* option).
Calibration run_calibration(const mesh::TriangleMesh& cell,
                            const membrane::MembraneParameters& parameters,
                            const CalibrationSettings& settings);

// {"hexagonal", "hexagonal_fit", "two_triangle", "two_triangle_fit", "overall_bending",
//  "overall_bending_fit", "stretch_fit", "paper"} (schemas/result.schema.json); the fits only when
// run.
nlohmann::ordered_json calibrate_result_section(const Calibration& calibration);
// {"membrane": {the fitted k}}: a config file that --config accepts. After a stretch fit also
// {"stretch": {"contact": ...}}, the contact the k_l was fitted under: `rbcsim stretch --config`
// with this file then runs the fitted curve.
nlohmann::ordered_json fitted_parameters_document(const Calibration& calibration);

}  // namespace rbcsim::cases
