#include "setup/shear_from_config.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/range.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/coupling_from_config.hpp"

namespace rbcsim::setup {
namespace {

// "0:2000" without a step: 0, 500, ..., 2000, the spacing of the paper's Figs. 9-11.
constexpr std::size_t kDefaultRateCount = 5;

}  // namespace

std::vector<double> shear_rates_from(std::string_view text, std::string_view source) {
  auto rates = config::parse_range(text, source, kDefaultRateCount);
  if (std::any_of(rates.begin(), rates.end(), [](double rate) { return rate < 0.0; })) {
    throw InputError(std::string(source),
                     "shear rates must be >= 0 1/s (the flow direction is fixed)");
  }
  return rates;
}

cases::ShearSettings shear_settings_from(const config::Config& config) {
  cases::ShearSettings settings;
  settings.rates_per_s = shear_rates_from(config.string("shear.rates_per_s"), "shear.rates_per_s");
  settings.boundary = config.string("shear.boundary");
  settings.gap_diameters = config.number("shear.gap_diameters");
  settings.width_diameters = config.number("shear.width_diameters");
  settings.max_strain = config.number("shear.max_strain");
  settings.steady_tolerance_per_strain = config.number("shear.steady_tolerance_per_strain");
  settings.check_interval_strain = config.number("shear.check_interval_strain");
  settings.viscosity_scaling = config.boolean("shear.viscosity_scaling");
  settings.max_reynolds_number = config.number("shear.max_reynolds_number");
  return settings;
}

cases::ShearEngine shear_engine_from(const config::Config& config,
                                     const std::filesystem::path& run_directory) {
  cases::ShearEngine engine;
  engine.lattice = {config.number("lattice.spacing_um"), config.number("lattice.relaxation_time"),
                    config.number("physics.plasma_density_kg_per_m3"),
                    config.number("physics.plasma_kinematic_viscosity_m2_per_s")};
  engine.fluid = fluid_parameters_from(config);
  engine.coupling = coupling_parameters_from(config, run_directory);
  return engine;
}

void require_cell_fits_shear_box(const mesh::TriangleMesh& cell,
                                 const cases::ShearSettings& settings,
                                 const cases::ShearEngine& engine) {
  const double spacing_um = engine.lattice.spacing_um;
  const auto box = cases::shear_box(cell, spacing_um, settings);
  const Vec3 fluid_extent_um = spacing_um * Vec3(box.nx, box.gap_nodes(), box.nz);
  require_cell_fits_domain(cell, fluid_extent_um, spacing_um, engine.coupling.kernel,
                           "shear box (shear.width_diameters, shear.gap_diameters, "
                           "lattice.spacing_um = " +
                               format_number(spacing_um) + " um)");
}

}  // namespace rbcsim::setup
