#include "cases/calibration.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>
#include <utility>

#include "cases/stretch_output.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/registry.hpp"
#include "membrane/hinge.hpp"
#include "mesh/inspection.hpp"

namespace rbcsim::cases {
namespace {

// ---- the patch edge a -----------------------------------------------------------------------

struct PatchEdgeRule {
  std::string_view name;
  double (*edge_um)(const mesh::TriangleMesh& cell, const membrane::MembraneParameters& p);
};

constexpr std::array<PatchEdgeRule, 2> kPatchEdgeRules{{
    {"mesh-mean-edge",
     [](const mesh::TriangleMesh& cell, const membrane::MembraneParameters&) {
       return mesh::inspect_mesh(cell).edge_mean_um;
     }},
    {"force-length-scale",
     [](const mesh::TriangleMesh&, const membrane::MembraneParameters& parameters) {
       return parameters.force_length_scale_um;
     }},
}};

// ---- the in-plane targets, as (mu, K) -------------------------------------------------------

struct InPlaneTarget {
  double shear_uN_per_m;
  double area_uN_per_m;
  const char* option;  // the option that names K, for the unreachable-target diagnostic
};

struct TargetModuliKind {
  std::string_view name;
  InPlaneTarget (*convert)(const CalibrationTargets& targets);
};

constexpr std::array<TargetModuliKind, 2> kTargetModuliKinds{{
    {"shear-area",
     [](const CalibrationTargets& targets) {
       return InPlaneTarget{targets.shear_uN_per_m, targets.area_uN_per_m,
                            "calibrate.target.area_modulus_uN_per_m"};
     }},
    // 2D isotropic: E = 2 mu (1 + nu) = 2 K (1 - nu).
    {"young-poisson",
     [](const CalibrationTargets& targets) {
       return InPlaneTarget{targets.young_uN_per_m / (2.0 * (1.0 + targets.poisson_ratio)),
                            targets.young_uN_per_m / (2.0 * (1.0 - targets.poisson_ratio)),
                            "calibrate.target.poisson_ratio"};
     }},
}};

double relative_error(double achieved, double target) {
  return std::abs(achieved - target) / std::abs(target);
}

// ---- the fits -------------------------------------------------------------------------------

// mu = k_l mu_link + k_a mu_area, K = k_l K_link + k_a K_area: one 2x2 solve.
void fit_link_area(const mesh::TriangleMesh&, Calibration& calibration) {
  const auto& targets = calibration.settings.targets;
  const auto target =
      find_entry(kTargetModuliKinds, targets.moduli, "calibrate.target.moduli").convert(targets);
  const auto& unit = calibration.unit_patch;
  const Eigen::Matrix2d response{{unit.link_shear_uN_per_m, unit.area_term_shear_uN_per_m},
                                 {unit.link_area_uN_per_m, unit.area_term_area_uN_per_m}};
  const Eigen::Vector2d k =
      response.fullPivLu().solve(Eigen::Vector2d(target.shear_uN_per_m, target.area_uN_per_m));
  if (k.minCoeff() < 0.0) {
    throw InputError(target.option,
                     "no k_link, k_area >= 0 gives mu = " + format_number(target.shear_uN_per_m) +
                         " and K = " + format_number(target.area_uN_per_m) +
                         " uN/m: the links alone give K = " +
                         format_number(unit.link_area_uN_per_m / unit.link_shear_uN_per_m) +
                         " mu, the area term only adds to K (fit gives k_link " +
                         format_number(k(0)) + ", k_area " + format_number(k(1)) + " kBT)");
  }
  auto& fitted = calibration.fitted;
  fitted.k_link_kBT = k(0);
  fitted.k_area_kBT = k(1);
  LinkAreaFit fit;
  fit.target_shear_uN_per_m = target.shear_uN_per_m;
  fit.target_area_uN_per_m = target.area_uN_per_m;
  fit.k_link_kBT = k(0);
  fit.k_area_kBT = k(1);
  fit.achieved =
      measure_hexagonal_patch(fitted, calibration.patch_edge_um, calibration.settings.strain)
          .network;
  fit.relative_residual =
      std::max(relative_error(fit.achieved.shear_uN_per_m, target.shear_uN_per_m),
               relative_error(fit.achieved.area_uN_per_m, target.area_uN_per_m));
  calibration.link_area = fit;
}

// D = k_b D_1.
void fit_bend(const mesh::TriangleMesh&, Calibration& calibration) {
  const double target_J = calibration.settings.targets.bending_modulus_J;
  auto& fitted = calibration.fitted;
  fitted.k_bend_kBT = target_J / calibration.unit_bending_modulus_J;
  StiffnessFit fit{target_J, 0.0, 0.0};
  fit.achieved_J =
      measure_two_triangle_patch(fitted, calibration.patch_edge_um, calibration.settings.angle_rad)
          .bending_modulus_J;
  fit.relative_residual = relative_error(fit.achieved_J, target_J);
  calibration.bend = fit;
}

// kappa = D_1 (k_b + (k_ad E_ad + k_c E_tc) / E_b) with k_ad = r k_c, at the (fitted) k_b.
void fit_curvature_terms(const mesh::TriangleMesh& cell, Calibration& calibration) {
  const auto& settings = calibration.settings;
  const double target_J = settings.targets.overall_bending_modulus_J;
  auto& fitted = calibration.fitted;
  const double unit_J = calibration.unit_bending_modulus_J;
  const auto& unit = calibration.unit_curvature;
  const double bend_only_J = unit_J * fitted.k_bend_kBT;
  if (target_J < bend_only_J) {
    throw InputError("calibrate.target.overall_bending_modulus_J",
                     format_number(target_J) +
                         " J is below the bending term's own D = " + format_number(bend_only_J) +
                         " J at k_bend " + format_number(fitted.k_bend_kBT) +
                         " kBT: the area-difference and total-curvature terms only add to it");
  }
  const double ratio = settings.area_difference_per_total_curvature;
  if (unit.area_difference_pN_um == 0.0 && unit.total_curvature_pN_um == 0.0) {
    throw InputError("calibrate.fits",
                     "curvature_terms needs area_difference or total_curvature in "
                     "membrane.forces");
  }
  fitted.k_total_curvature_kBT = (target_J / unit_J - fitted.k_bend_kBT) * unit.bend_pN_um /
                                 (ratio * unit.area_difference_pN_um + unit.total_curvature_pN_um);
  fitted.k_area_difference_kBT = ratio * fitted.k_total_curvature_kBT;
  // Measured again at the fitted k: D of the pair and the energies of the cell's mode.
  const double bending_J =
      measure_two_triangle_patch(fitted, calibration.patch_edge_um, settings.angle_rad)
          .bending_modulus_J;
  const auto stiffness = measure_uniform_curvature_stiffness(cell, fitted, settings.angle_rad);
  StiffnessFit fit{target_J, 0.0, 0.0};
  fit.achieved_J =
      bending_J * (1.0 + (stiffness.area_difference_pN_um + stiffness.total_curvature_pN_um) /
                             stiffness.bend_pN_um);
  fit.relative_residual = relative_error(fit.achieved_J, target_J);
  calibration.curvature_terms = fit;
}

// k_l to the stretch curve (stretch_fit.hpp), with the other k as configured or fitted above.
void fit_stretch(const mesh::TriangleMesh& cell, Calibration& calibration) {
  auto curve = fit_stretch_k_link(cell, calibration.fitted, calibration.settings.stretch_fit);
  auto& fitted = calibration.fitted;
  fitted.k_link_kBT = curve.best.k_link_kBT;
  const auto achieved =
      measure_hexagonal_patch(fitted, calibration.patch_edge_um, calibration.settings.strain)
          .network;
  calibration.stretch = StretchCurveFit{std::move(curve), achieved};
}

struct CalibrationFit {
  std::string_view name;
  void (*fit)(const mesh::TriangleMesh& cell, Calibration& calibration);
};

// In execution order: the curvature fit builds on the fitted k_b, the stretch fit on every k.
constexpr std::array<CalibrationFit, 4> kFits{{
    {"link_area", fit_link_area},
    {"bend", fit_bend},
    {"curvature_terms", fit_curvature_terms},
    {"stretch", fit_stretch},
}};

membrane::MembraneParameters with_unit_stiffness(membrane::MembraneParameters parameters) {
  parameters.k_bend_kBT = 1.0;
  parameters.k_area_difference_kBT = 1.0;
  parameters.k_total_curvature_kBT = 1.0;
  return parameters;
}

void measure(const mesh::TriangleMesh& cell, Calibration& calibration) {
  const auto& settings = calibration.settings;
  const auto& parameters = calibration.configured;
  const double edge_um = calibration.patch_edge_um;
  calibration.hexagonal = measure_hexagonal_patch(parameters, edge_um, settings.strain);
  calibration.unit_patch = measure_patch_stiffness(parameters, edge_um, settings.strain);
  calibration.analytic_patch = analytic_patch_stiffness(parameters, edge_um);
  calibration.two_triangle = measure_two_triangle_patch(parameters, edge_um, settings.angle_rad);
  calibration.analytic_bending_modulus_J =
      analytic_two_triangle_bending_modulus_J(parameters, edge_um);
  const auto unit = with_unit_stiffness(parameters);
  calibration.unit_bending_modulus_J =
      measure_two_triangle_patch(unit, edge_um, settings.angle_rad).bending_modulus_J;
  calibration.unit_curvature = measure_uniform_curvature_stiffness(cell, unit, settings.angle_rad);
  calibration.overall_bending_modulus_J = overall_bending_modulus_J(
      calibration.unit_bending_modulus_J, calibration.unit_curvature, parameters.k_bend_kBT,
      parameters.k_area_difference_kBT, parameters.k_total_curvature_kBT);
}

// ---- result.json ----------------------------------------------------------------------------

nlohmann::ordered_json moduli_json(const MembraneModuli& moduli, const std::string& prefix = "") {
  return {{prefix + "E_s_uN_per_m", moduli.young_uN_per_m},
          {prefix + "mu_uN_per_m", moduli.shear_uN_per_m},
          {prefix + "K_uN_per_m", moduli.area_uN_per_m},
          {prefix + "poisson_ratio", moduli.poisson_ratio}};
}

nlohmann::ordered_json hexagonal_json(const Calibration& calibration) {
  const auto& parameters = calibration.configured;
  nlohmann::ordered_json section = {{"k_link_kBT", parameters.k_link_kBT},
                                    {"k_area_kBT", parameters.k_area_kBT},
                                    {"patch_edge_um", calibration.patch_edge_um},
                                    {"strain", calibration.settings.strain}};
  section.update(moduli_json(calibration.hexagonal.network));
  section.update(moduli_json(calibration.hexagonal.isolated, "isolated_patch_"));
  const auto analytic =
      network_moduli(calibration.analytic_patch, parameters.k_link_kBT, parameters.k_area_kBT);
  section.update(moduli_json(analytic, "analytic_"));
  section["centre_residual_force_pN"] = calibration.hexagonal.largest_centre_force_pN;
  return section;
}

nlohmann::ordered_json link_area_fit_json(const LinkAreaFit& fit) {
  nlohmann::ordered_json section = {{"target_mu_uN_per_m", fit.target_shear_uN_per_m},
                                    {"target_K_uN_per_m", fit.target_area_uN_per_m},
                                    {"k_link_kBT", fit.k_link_kBT},
                                    {"k_area_kBT", fit.k_area_kBT}};
  section.update(moduli_json(fit.achieved));
  section["relative_residual"] = fit.relative_residual;
  return section;
}

nlohmann::ordered_json two_triangle_json(const Calibration& calibration) {
  const auto& patch = calibration.two_triangle;
  return {{"k_bend_kBT", calibration.configured.k_bend_kBT},
          {"fold_rad", calibration.settings.angle_rad},
          {"hinge_distance_um", patch.hinge_distance_um},
          {"moment_per_angle_pN_um", patch.moment_per_angle_pN_um},
          {"bending_modulus_J", patch.bending_modulus_J},
          {"analytic_bending_modulus_J", calibration.analytic_bending_modulus_J}};
}

nlohmann::ordered_json overall_bending_json(const Calibration& calibration) {
  const auto& parameters = calibration.configured;
  const auto& unit = calibration.unit_curvature;
  const double bend = parameters.k_bend_kBT * unit.bend_pN_um;
  return {{"k_bend_kBT", parameters.k_bend_kBT},
          {"k_area_difference_kBT", parameters.k_area_difference_kBT},
          {"k_total_curvature_kBT", parameters.k_total_curvature_kBT},
          {"area_difference_per_bend",
           parameters.k_area_difference_kBT * unit.area_difference_pN_um / bend},
          {"total_curvature_per_bend",
           parameters.k_total_curvature_kBT * unit.total_curvature_pN_um / bend},
          {"bending_modulus_J", calibration.overall_bending_modulus_J}};
}

nlohmann::ordered_json stiffness_fit_json(const StiffnessFit& fit,
                                          const membrane::MembraneParameters& fitted,
                                          bool with_curvature_terms) {
  nlohmann::ordered_json section = {{"target_bending_modulus_J", fit.target_J},
                                    {"k_bend_kBT", fitted.k_bend_kBT}};
  if (with_curvature_terms) {
    section["k_area_difference_kBT"] = fitted.k_area_difference_kBT;
    section["k_total_curvature_kBT"] = fitted.k_total_curvature_kBT;
  }
  section["bending_modulus_J"] = fit.achieved_J;
  section["relative_residual"] = fit.relative_residual;
  return section;
}

nlohmann::ordered_json stretch_fit_json(const StretchCurveFit& fit) {
  const auto& best = fit.curve.best;
  nlohmann::ordered_json section = {{"start_k_link_kBT", fit.curve.start_k_link_kBT},
                                    {"k_link_kBT", best.k_link_kBT}};
  section.update(moduli_json(fit.achieved));
  section.update({{"misfit", best.misfit},
                  {"comparison", mills_comparison_json(best.comparison)},
                  {"curves", fit.curve.evaluations.size()}});
  return section;
}

// The paper's numbers under the same keys, test by test (the report puts them side by side).
nlohmann::ordered_json paper_json() {
  using Paper = PaperCalibration;
  const nlohmann::ordered_json moduli = {{"E_s_uN_per_m", Paper::young_uN_per_m},
                                         {"mu_uN_per_m", Paper::shear_uN_per_m},
                                         {"K_uN_per_m", Paper::area_uN_per_m},
                                         {"poisson_ratio", Paper::poisson_ratio}};
  nlohmann::ordered_json hexagonal = {{"k_link_kBT", Paper::k_link_kBT},
                                      {"k_area_kBT", Paper::k_area_kBT}};
  hexagonal.update(moduli);
  nlohmann::ordered_json hexagonal_fit = {{"target_mu_uN_per_m", Paper::shear_uN_per_m},
                                          {"target_K_uN_per_m", Paper::area_uN_per_m},
                                          {"k_link_kBT", Paper::k_link_kBT},
                                          {"k_area_kBT", Paper::k_area_kBT}};
  hexagonal_fit.update(moduli);
  const nlohmann::ordered_json two_triangle = {{"k_bend_kBT", Paper::k_bend_kBT},
                                               {"bending_modulus_J", Paper::bending_modulus_J}};
  const nlohmann::ordered_json overall = {{"k_bend_kBT", Paper::k_bend_kBT},
                                          {"k_area_difference_kBT", Paper::k_area_difference_kBT},
                                          {"k_total_curvature_kBT", Paper::k_total_curvature_kBT},
                                          {"bending_modulus_J", Paper::overall_bending_modulus_J}};
  nlohmann::ordered_json two_triangle_fit = two_triangle;
  two_triangle_fit["target_bending_modulus_J"] = Paper::bending_modulus_J;
  nlohmann::ordered_json overall_fit = overall;
  overall_fit["target_bending_modulus_J"] = Paper::overall_bending_modulus_J;
  // Table 2's k_link and the modulus the paper gives for it; the paper fits nothing to a stretch.
  nlohmann::ordered_json stretch_fit = {{"k_link_kBT", Paper::k_link_kBT}};
  stretch_fit.update(moduli);
  return {{"hexagonal", hexagonal},       {"hexagonal_fit", hexagonal_fit},
          {"two_triangle", two_triangle}, {"two_triangle_fit", two_triangle_fit},
          {"overall_bending", overall},   {"overall_bending_fit", overall_fit},
          {"stretch_fit", stretch_fit}};
}

}  // namespace

std::vector<std::string> calibration_fit_names() { return entry_names(kFits); }
std::vector<std::string> patch_edge_rule_names() { return entry_names(kPatchEdgeRules); }
std::vector<std::string> target_moduli_names() { return entry_names(kTargetModuliKinds); }

Calibration run_calibration(const mesh::TriangleMesh& cell,
                            const membrane::MembraneParameters& parameters,
                            const CalibrationSettings& settings) {
  for (const auto& name : settings.fits) {
    find_entry(kFits, name, "calibrate.fits");
  }
  // The patch tests fold single hinges and shift every theta0; the vertex form's reference is a
  // per-vertex offset that neither moves.
  if (membrane::is_vertex_distribution(parameters.distribution)) {
    throw InputError("membrane.distribution",
                     "calibrate's patch tests measure the hinge forms (paper, gradient); the "
                     "vertex form acts on whole vertex rings and has no two-triangle patch");
  }
  Calibration calibration;
  calibration.settings = settings;
  calibration.configured = parameters;
  calibration.fitted = parameters;
  calibration.patch_edge_um =
      find_entry(kPatchEdgeRules, settings.patch_edge, "calibrate.patch_edge")
          .edge_um(cell, parameters);
  measure(cell, calibration);
  for (const auto& fit : kFits) {
    if (std::find(settings.fits.begin(), settings.fits.end(), fit.name) != settings.fits.end()) {
      fit.fit(cell, calibration);
    }
  }
  return calibration;
}

nlohmann::ordered_json calibrate_result_section(const Calibration& calibration) {
  nlohmann::ordered_json section;
  section["hexagonal"] = hexagonal_json(calibration);
  if (calibration.link_area) section["hexagonal_fit"] = link_area_fit_json(*calibration.link_area);
  section["two_triangle"] = two_triangle_json(calibration);
  if (calibration.bend) {
    section["two_triangle_fit"] = stiffness_fit_json(*calibration.bend, calibration.fitted, false);
  }
  section["overall_bending"] = overall_bending_json(calibration);
  if (calibration.curvature_terms) {
    section["overall_bending_fit"] =
        stiffness_fit_json(*calibration.curvature_terms, calibration.fitted, true);
  }
  if (calibration.stretch) section["stretch_fit"] = stretch_fit_json(*calibration.stretch);
  section["paper"] = paper_json();
  return section;
}

nlohmann::ordered_json fitted_parameters_document(const Calibration& calibration) {
  const auto& fitted = calibration.fitted;
  nlohmann::ordered_json membrane = nlohmann::ordered_json::object();
  if (calibration.link_area) {
    membrane["k_link_kBT"] = fitted.k_link_kBT;
    membrane["k_area_kBT"] = fitted.k_area_kBT;
  }
  if (calibration.bend) membrane["k_bend_kBT"] = fitted.k_bend_kBT;
  if (calibration.curvature_terms) {
    membrane["k_area_difference_kBT"] = fitted.k_area_difference_kBT;
    membrane["k_total_curvature_kBT"] = fitted.k_total_curvature_kBT;
  }
  if (!calibration.stretch) return {{"membrane", membrane}};
  membrane["k_link_kBT"] = fitted.k_link_kBT;
  const auto& contact = calibration.settings.stretch_fit.stretch.contact;
  const nlohmann::ordered_json contact_json = {
      {"rule", contact.rule},
      {"diameter_um", contact.diameter_um},
      {"extreme_vertex_count", contact.extreme_vertex_count},
      {"rigid", contact.rigid}};
  return {{"membrane", membrane}, {"stretch", {{"contact", contact_json}}}};
}

}  // namespace rbcsim::cases
