#include "setup/capillary_from_config.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "cases/capillary_observables.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "geometry/wall_registry.hpp"
#include "mesh/import.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/membrane_from_config.hpp"

namespace rbcsim::setup {
namespace {

constexpr double kMetresPerMicrometre = 1e-6;

mesh::TriangleMesh load_wall_mesh(const std::string& path) { return mesh::import_mesh(path).mesh; }

nlohmann::json built_in_parameters(const config::Config& config) {
  nlohmann::json parameters = {{"profile", config.string("capillary.profile")}};
  for (const char* key : {"throat_diameter_um", "constriction_length_um"}) {
    const double value = config.number(std::string("capillary.") + key);
    if (value > 0.0) parameters[key] = value;
  }
  return parameters;
}

double paper_reynolds_number(const std::string& geometry) {
  return geometry == "paper-morphology" ? kPaperMorphologyReynoldsNumber
                                        : kPaperValidationReynoldsNumber;
}

// The time the mean inlet flow takes to cross the fluid box along x. A cell on the axis moves
// faster than the mean: passing cells need about a third of it at every velocity we ran
// (docs/validation.md, capillary), so as a time limit it stops a stuck cell without cutting a slow
// run short.
double mean_flow_crossing_time_s(const CapillaryWall& wall, double mean_inlet_velocity_m_per_s) {
  const auto bounds = wall.shape->fluid_bounds();
  return (bounds.max_um.x() - bounds.min_um.x()) * kMetresPerMicrometre /
         mean_inlet_velocity_m_per_s;
}

}  // namespace

CapillaryWall capillary_wall_from(const config::Config& config) {
  const auto file = config.string("capillary.wall_file");
  if (!file.empty()) {
    const nlohmann::json parameters = {{"file", file}, {"open_axes", {"x"}}};
    return {geometry::make_wall_shape("stl", parameters, "capillary.wall_file", load_wall_mesh),
            file, file};
  }
  const auto geometry = config.string("capillary.geometry");
  return {geometry::make_wall_shape(geometry, built_in_parameters(config), "capillary"), geometry,
          "capillary.geometry"};
}

cases::CapillarySettings capillary_settings_from(const config::Config& config,
                                                 const CapillaryWall& wall) {
  cases::CapillarySettings settings;
  settings.mean_inlet_velocity_m_per_s = config.number("capillary.inlet_velocity_m_per_s");
  if (settings.mean_inlet_velocity_m_per_s == 0.0) {
    const auto radius_um = wall.shape->radius_at_um(0.0);
    if (!radius_um) {
      throw InputError("capillary.inlet_velocity_m_per_s",
                       "give the inlet velocity (the paper's Reynolds numbers are for its built-in "
                       "capillaries only)");
    }
    settings.mean_inlet_velocity_m_per_s =
        paper_reynolds_number(wall.geometry) *
        config.number("physics.plasma_kinematic_viscosity_m2_per_s") /
        (2.0 * *radius_um * kMetresPerMicrometre);
  }
  settings.cell_axis = config.string("capillary.cell_axis");
  settings.release_gap_um = config.number("capillary.release_gap_um");
  settings.pass_margin_um = config.number("capillary.pass_margin_um");
  settings.wall_repulsion_pN_per_um2 = config.number("capillary.wall_repulsion_pN_per_um2");
  settings.wall_repulsion_range_um = config.number("capillary.wall_repulsion_range_um");
  settings.max_time_s = config.number("capillary.max_time_s");
  if (settings.max_time_s == 0.0) {
    settings.max_time_s = mean_flow_crossing_time_s(wall, settings.mean_inlet_velocity_m_per_s);
  }
  settings.sample_interval_s = config.number("capillary.sample_interval_s");
  settings.fluid_tolerance = config.number("capillary.fluid_tolerance");
  settings.fluid_max_steps = static_cast<std::size_t>(config.integer("capillary.fluid_max_steps"));
  return settings;
}

cases::CapillaryPhysics capillary_physics_from(const config::Config& config,
                                               const CapillaryWall& wall,
                                               const mesh::TriangleMesh& cell,
                                               const std::filesystem::path& run_directory) {
  return {*wall.shape,
          wall.source,
          cell_membrane_parameters_from(config, cell),
          fluid_parameters_from(config),
          coupling_parameters_from(config, run_directory),
          config::make_unit_converter(config),
          config.number("physics.plasma_density_kg_per_m3"),
          config.number("physics.plasma_kinematic_viscosity_m2_per_s"),
          config.number("physics.thermal_energy_J")};
}

double low_reynolds_compression_factor(double physical_reynolds_number,
                                       double max_reynolds_number) {
  if (physical_reynolds_number >= max_reynolds_number) return 1.0;
  return std::sqrt(max_reynolds_number / physical_reynolds_number);
}

CapillaryCompression capillary_compression_from(const config::Config& config,
                                                const CapillaryWall& wall) {
  CapillaryCompression compression;
  const double velocity = capillary_settings_from(config, wall).mean_inlet_velocity_m_per_s;
  const double viscosity = config.number("physics.plasma_kinematic_viscosity_m2_per_s");
  compression.simulated_inlet_velocity_m_per_s = velocity;
  compression.simulated_kinematic_viscosity_m2_per_s = viscosity;
  const auto radius_um = wall.shape->radius_at_um(0.0);
  if (!radius_um) return compression;
  compression.physical_reynolds_number =
      velocity * 2.0 * *radius_um * kMetresPerMicrometre / viscosity;
  compression.simulated_reynolds_number = compression.physical_reynolds_number;
  const double limit = config.number("capillary.max_reynolds_number");
  if (!config.boolean("capillary.time_scale_compression")) return compression;
  compression.factor =
      low_reynolds_compression_factor(compression.physical_reynolds_number, limit);
  if (compression.factor == 1.0) return compression;
  compression.simulated_reynolds_number = limit;
  compression.simulated_inlet_velocity_m_per_s = velocity * compression.factor;
  compression.simulated_kinematic_viscosity_m2_per_s = viscosity / compression.factor;
  return compression;
}

config::Config compressed_capillary_config(const config::Config& config, const CapillaryWall& wall,
                                           const CapillaryCompression& compression) {
  const double s = compression.factor;
  if (s == 1.0) return config;
  // The physical velocity first: a zero (the paper's Reynolds number) is resolved with the
  // physical viscosity.
  const double velocity = capillary_settings_from(config, wall).mean_inlet_velocity_m_per_s;
  auto compressed = config
                        .with("physics.plasma_kinematic_viscosity_m2_per_s",
                              compression.simulated_kinematic_viscosity_m2_per_s)
                        .with("capillary.inlet_velocity_m_per_s", velocity * s)
                        // The membrane's viscosity keeps its ratio to the plasma's (the
                        // Boussinesq number eta_m / (eta R)), as the cytoplasm's does.
                        .with("membrane.viscosity_Pa_s_um",
                              config.number("membrane.viscosity_Pa_s_um") / s);
  // A zero max_time_s is resolved from the (compressed) velocity; zero intervals mean "none".
  for (const char* time : {"capillary.max_time_s", "capillary.sample_interval_s",
                           "output.membrane_interval_s", "output.fluid_interval_s"}) {
    compressed = compressed.with(time, config.number(time) / s);
  }
  return compressed;
}

void to_physical_units(cases::CapillaryRun& run, const CapillaryCompression& compression) {
  const double s = compression.factor;
  if (s == 1.0) return;
  for (auto& sample : run.samples) {
    sample.time_s *= s;
    sample.velocity_x_m_per_s /= s;
  }
  for (auto* time :
       {&run.entry_time_s, &run.exit_time_s, &run.transit_time_s, &run.front_entry_time_s,
        &run.rear_exit_time_s, &run.whole_cell_transit_time_s}) {
    if (*time) **time *= s;
  }
  run.peak_time_s *= s;
  run.time_s *= s;
  run.numbers.mean_inlet_velocity_m_per_s /= s;
  run.numbers.reynolds_number /= s * s;
  const std::string note =
      " (times in this message are simulated ones: physical = " + format_number(s) +
      " x simulated, capillary.time_scale_compression)";
  if (!run.stop_reason.empty()) run.stop_reason += note;
  if (!run.failure.empty()) run.failure += note;
}

}  // namespace rbcsim::setup
