#include "setup/stretch_from_config.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cases/fluid_stretch.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/embedded_share.hpp"
#include "config/range.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/coupling_from_config.hpp"

namespace rbcsim::setup {
namespace {

constexpr std::string_view kReferenceForces = "mills2004";
constexpr std::string_view kMillsFile = "mills2004_stretch.csv";
// "0:200" without a step: every 25 pN, the spacing of a typical tweezers sweep.
constexpr std::size_t kDefaultForceCount = 9;

cases::FluidStretchSettings fluid_stretch_settings_from(const config::Config& config) {
  cases::FluidStretchSettings settings;
  settings.lattice = {config.number("lattice.spacing_um"), config.number("lattice.relaxation_time"),
                      config.number("physics.plasma_density_kg_per_m3"),
                      config.number("stretch.fluid.kinematic_viscosity_m2_per_s")};
  settings.fluid = fluid_parameters_from(config);
  settings.coupling = coupling_parameters_from(config, {});
  settings.box_margin_um = config.number("stretch.fluid.box_margin_um");
  settings.force_ramp_time_s = config.number("stretch.fluid.force_ramp_time_s");
  settings.warm_start = config.boolean("stretch.fluid.warm_start");
  settings.steady.relative_rate_per_s = config.number("stretch.fluid.steady_relative_rate_per_s");
  settings.steady.check_interval_s = config.number("stretch.fluid.steady_check_interval_s");
  settings.max_time_per_force_s = config.number("stretch.fluid.max_time_per_force_s");
  settings.snapshot_interval_s = config.number("stretch.fluid.snapshot_interval_s");
  settings.snapshot_format = snapshot_format_from(config);
  return settings;
}

}  // namespace

io::CsvTable embedded_reference_table(std::string_view file_name) {
  const auto relative_path = "reference/" + std::string(file_name);
  const auto text = config::find_embedded_share_file(relative_path);
  if (!text) throw std::logic_error("share/" + relative_path + " is not embedded in the binary");
  return io::CsvTable::parse(*text, "share/" + relative_path);
}

std::vector<cases::StretchReferencePoint> mills2004_stretch_reference() {
  return cases::stretch_reference_from(embedded_reference_table(kMillsFile));
}

std::vector<double> stretch_forces_from(std::string_view text, std::string_view source) {
  if (text == kReferenceForces) {
    std::vector<double> forces;
    for (const auto& point : mills2004_stretch_reference()) forces.push_back(point.force_pN);
    return forces;
  }
  auto forces = config::parse_range(text, source, kDefaultForceCount);
  if (std::any_of(forces.begin(), forces.end(), [](double f) { return f < 0.0; })) {
    throw InputError(std::string(source), "forces must be >= 0 pN (the tweezers pull)");
  }
  return forces;
}

cases::StretchSettings stretch_settings_from(const config::Config& config) {
  cases::StretchSettings settings;
  settings.mode = config.string("stretch.mode");
  settings.forces_pN = stretch_forces_from(config.string("stretch.forces_pN"), "stretch.forces_pN");
  settings.contact.rule = config.string("stretch.contact.rule");
  settings.contact.diameter_um = config.number("stretch.contact.diameter_um");
  settings.contact.extreme_vertex_count = config.integer("stretch.contact.extreme_vertex_count");
  settings.contact.rigid = config.boolean("stretch.contact.rigid");
  settings.relaxation = config.string("stretch.quasi_static.relaxation");
  settings.relaxation_settings.force_tolerance_pN =
      config.number("stretch.quasi_static.force_tolerance_pN");
  settings.relaxation_settings.max_iterations =
      static_cast<std::size_t>(config.integer("stretch.quasi_static.max_iterations"));
  settings.fluid = fluid_stretch_settings_from(config);
  return settings;
}

void require_cell_fits_stretch_box(const mesh::TriangleMesh& cell,
                                   const cases::StretchSettings& settings) {
  if (settings.mode != "fluid") return;  // the quasi-static mode has no fluid domain
  const double spacing_um = settings.fluid.lattice.spacing_um;
  const auto box = cases::stretch_box(cell.positions_um, spacing_um, settings.fluid.box_margin_um);
  const Vec3 fluid_extent_um = spacing_um * Vec3(box.nodes[0], box.nodes[1], box.nodes[2]);
  require_cell_fits_domain(
      cell, fluid_extent_um, spacing_um, settings.fluid.coupling.kernel,
      "stretch box (stretch.fluid.box_margin_um = " + format_number(settings.fluid.box_margin_um) +
          " um, lattice.spacing_um = " + format_number(spacing_um) + " um)");
}

}  // namespace rbcsim::setup
