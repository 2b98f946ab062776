#include "setup/calibrate_from_config.hpp"

#include "setup/stretch_from_config.hpp"

namespace rbcsim::setup {

cases::CalibrationSettings calibration_settings_from(const config::Config& config) {
  cases::CalibrationSettings settings;
  settings.fits = config.string_list("calibrate.fits");
  settings.patch_edge = config.string("calibrate.patch_edge");
  settings.strain = config.number("calibrate.strain");
  settings.angle_rad = config.number("calibrate.angle_rad");
  settings.area_difference_per_total_curvature =
      config.number("calibrate.area_difference_per_total_curvature");
  auto& targets = settings.targets;
  targets.moduli = config.string("calibrate.target.moduli");
  targets.shear_uN_per_m = config.number("calibrate.target.shear_modulus_uN_per_m");
  targets.area_uN_per_m = config.number("calibrate.target.area_modulus_uN_per_m");
  targets.young_uN_per_m = config.number("calibrate.target.young_modulus_uN_per_m");
  targets.poisson_ratio = config.number("calibrate.target.poisson_ratio");
  targets.bending_modulus_J = config.number("calibrate.target.bending_modulus_J");
  targets.overall_bending_modulus_J = config.number("calibrate.target.overall_bending_modulus_J");
  // The stretch fit runs the stretch as configured (stretch.contact.*, stretch.quasi_static.*
  // but its own iteration budget) against Mills et al. (2004).
  auto& stretch_fit = settings.stretch_fit;
  stretch_fit.stretch = stretch_settings_from(config);
  stretch_fit.reference = mills2004_stretch_reference();
  stretch_fit.relative_tolerance = config.number("calibrate.stretch_fit.relative_tolerance");
  stretch_fit.max_iterations_per_force =
      static_cast<std::size_t>(config.integer("calibrate.stretch_fit.max_iterations_per_force"));
  return settings;
}

}  // namespace rbcsim::setup
