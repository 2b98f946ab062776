#include "cases/calibration.hpp"
#include "config/options/option_areas.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the case's settings struct: one source of truth.
const cases::CalibrationSettings kCalibrateDefaults{};

void add_target_options(OptionTable& table) {
  const auto& targets = kCalibrateDefaults.targets;
  table.add_choice("calibrate.target.moduli", cases::target_moduli_names(), targets.moduli,
                   "In-plane targets of the link_area fit: shear and area-compression moduli, "
                   "or Young's modulus and Poisson ratio.");
  table
      .add_number("calibrate.target.shear_modulus_uN_per_m", "uN/m", targets.shear_uN_per_m,
                  "Target shear modulus mu (paper §2.3: 10.15).")
      .above(0.0);
  table
      .add_number("calibrate.target.area_modulus_uN_per_m", "uN/m", targets.area_uN_per_m,
                  "Target area-compression modulus K (paper §2.3: 28.2).")
      .above(0.0);
  table
      .add_number("calibrate.target.young_modulus_uN_per_m", "uN/m", targets.young_uN_per_m,
                  "Target 2D Young's modulus E_s (paper §2.3: 29.85), with target.moduli = "
                  "young-poisson.")
      .above(0.0);
  table
      .add_number("calibrate.target.poisson_ratio", "", targets.poisson_ratio,
                  "Target 2D Poisson ratio (paper §2.3: 0.33), with target.moduli = "
                  "young-poisson.")
      .above(-1.0)
      .below(1.0);
  table
      .add_number("calibrate.target.bending_modulus_J", "J", targets.bending_modulus_J,
                  "Target bending stiffness D of the two-triangle patch (paper: k_b = 50 kBT "
                  "~ 2e-19 J).")
      .above(0.0);
  table
      .add_number("calibrate.target.overall_bending_modulus_J", "J",
                  targets.overall_bending_modulus_J,
                  "Target overall bending modulus of the cell with the area-difference and "
                  "total-curvature terms (paper: ~2.5e-19 J).")
      .above(0.0);
}

}  // namespace

void add_calibrate_options(OptionTable& table) {
  table.add_choice_list("calibrate.fits", cases::calibration_fit_names(), kCalibrateDefaults.fits,
                        "Fits to run: link_area (k_link, k_area to the in-plane targets), bend "
                        "(k_bend to D), curvature_terms (k_area_difference, k_total_curvature to "
                        "the overall bending modulus), stretch (k_link to the optical-tweezers "
                        "curve of Mills et al. 2004 with stretch.contact.* and "
                        "stretch.quasi_static.*; minutes, not run by default).");
  table.add_choice("calibrate.patch_edge", cases::patch_edge_rule_names(),
                   kCalibrateDefaults.patch_edge,
                   "Rest edge of the patches: the cell mesh's mean edge (the k are "
                   "mesh-dependent) or membrane.force_length_scale_um (Table 2's L0).");
  table
      .add_number("calibrate.strain", "", kCalibrateDefaults.strain,
                  "Strain amplitude of the hexagonal patch tests (central differences).")
      .above(0.0)
      .at_most(0.05);
  table
      .add_number("calibrate.angle_rad", "rad", kCalibrateDefaults.angle_rad,
                  "Fold of the two-triangle patch and uniform dihedral perturbation of the cell.")
      .above(0.0)
      .at_most(0.05);
  table
      .add_number("calibrate.area_difference_per_total_curvature", "",
                  kCalibrateDefaults.area_difference_per_total_curvature,
                  "Ratio k_area_difference / k_total_curvature kept by the curvature_terms fit "
                  "(the paper's 300 / 100).")
      .above(0.0);
  table
      .add_number("calibrate.stretch_fit.relative_tolerance", "",
                  kCalibrateDefaults.stretch_fit.relative_tolerance,
                  "The stretch fit's k_link is known to within this fraction.")
      .above(0.0)
      .at_most(0.1);
  table
      .add_integer(
          "calibrate.stretch_fit.max_iterations_per_force", "",
          static_cast<int>(kCalibrateDefaults.stretch_fit.max_iterations_per_force),
          "Relaxation iterations per force of the fit's curves (instead of "
          "stretch.quasi_static.max_iterations); a curve needing more counts as failed, which "
          "bounds the search. Near the softest k_link that carries Mills' forces the curves that "
          "converge need up to ~5000, the ones past it never converge.")
      .at_least(1);
  add_target_options(table);
}

}  // namespace rbcsim::config
