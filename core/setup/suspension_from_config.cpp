#include "setup/suspension_from_config.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "ibm/delta_kernels.hpp"
#include "mesh/geometry.hpp"
#include "setup/capillary_from_config.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/membrane_from_config.hpp"

namespace rbcsim::setup {
namespace {

constexpr const char* kMixOption = "suspension.mix";

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Fills the names and fractions of a non-empty suspension.mix.
void parse_mix(const std::string& text, SuspensionMix& mix) {
  std::stringstream entries(text);
  std::string entry;
  double sum = 0.0;
  while (std::getline(entries, entry, ',')) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos) {
      throw InputError(kMixOption, "'" + trimmed(entry) + "' is not morphology=fraction");
    }
    const auto name = trimmed(entry.substr(0, equals));
    const auto value = trimmed(entry.substr(equals + 1));
    double fraction = 0.0;
    try {
      std::size_t used = 0;
      fraction = std::stod(value, &used);
      if (used != value.size()) throw std::invalid_argument(value);
    } catch (const std::exception&) {
      throw InputError(kMixOption, "'" + value + "' (for " + name + ") is not a number");
    }
    if (!(fraction > 0.0 && fraction <= 1.0)) {
      throw InputError(kMixOption, "the fraction of " + name + " must lie in (0, 1]");
    }
    if (std::find(mix.names.begin(), mix.names.end(), name) != mix.names.end()) {
      throw InputError(kMixOption, name + " is listed twice");
    }
    // A morphology is known when it resolves (it has a Table 2 overlay).
    try {
      (void)config::resolve_config({.morphology = name});
    } catch (const InputError&) {
      throw InputError(kMixOption, "unknown morphology '" + name + "'");
    }
    mix.names.push_back(name);
    mix.fractions.push_back(fraction);
    sum += fraction;
  }
  if (std::abs(sum - 1.0) > 1e-6) {
    throw InputError(kMixOption, "the fractions sum to " + format_number(sum) + ", not 1");
  }
}

}  // namespace

SuspensionMix suspension_mix_from(const config::Config& config) {
  SuspensionMix mix;
  const auto text = config.string(kMixOption);
  const auto placed = config.cell_list("suspension.cells");
  if (!placed.empty()) {
    if (!trimmed(text).empty()) {
      throw InputError(kMixOption,
                       "suspension.cells names each cell's morphology: leave the mix "
                       "empty");
    }
    for (const auto& cell : placed) {
      const auto name = placed_kind_name(cell);
      if (std::find(mix.names.begin(), mix.names.end(), name) == mix.names.end()) {
        mix.names.push_back(name);
        mix.fractions.push_back(0.0);
        mix.morphologies.push_back(cell.morphology);
        mix.mesh_files.push_back(cell.mesh_file);
      }
      const auto m = static_cast<std::size_t>(std::find(mix.names.begin(), mix.names.end(), name) -
                                              mix.names.begin());
      mix.fractions[m] += 1.0 / static_cast<double>(placed.size());
    }
    return mix;
  }
  if (trimmed(text).empty()) {
    mix.names.push_back(config.string("morphology"));
    mix.fractions.push_back(1.0);
  } else {
    parse_mix(text, mix);
  }
  // Packed kinds are morphologies of their own shape.
  mix.morphologies = mix.names;
  mix.mesh_files.assign(mix.names.size(), std::string());
  return mix;
}

std::vector<std::size_t> packed_cell_kinds(
    std::span<const cases::SuspensionMorphology> morphologies, const SuspensionMix& mix,
    double volume_um3, double hematocrit) {
  std::vector<double> volumes_um3;
  for (const auto& morphology : morphologies) {
    volumes_um3.push_back(mesh::enclosed_volume_um3(morphology.mesh));
  }
  const auto counts = cases::cell_counts_for(hematocrit, volume_um3, mix.fractions, volumes_um3);
  std::vector<std::size_t> cells;
  for (std::size_t m = 0; m < counts.size(); ++m) cells.insert(cells.end(), counts[m], m);
  return cells;
}

std::vector<std::size_t> placed_cell_kinds(const SuspensionMix& mix,
                                           const std::vector<config::CellPlacement>& placed) {
  std::vector<std::size_t> cells;
  for (const auto& cell : placed) {
    const auto name = placed_kind_name(cell);
    cells.push_back(static_cast<std::size_t>(std::find(mix.names.begin(), mix.names.end(), name) -
                                             mix.names.begin()));
  }
  return cells;
}

namespace {

// What the tube's and the gap's suspensions share: the walls' push, the contact, the packing and
// the cells placed by hand.
template <class Settings>
void read_interactions(const config::Config& config, Settings& settings) {
  settings.averaging_fraction = config.number("suspension.averaging_fraction");
  for (const auto& cell : config.cell_list("suspension.cells")) {
    const auto vector = [](const std::array<double, 3>& v) { return Vec3(v[0], v[1], v[2]); };
    settings.placed_cells.push_back({vector(cell.centre_um), vector(cell.axis), cell.spin_deg});
  }
  settings.wall_repulsion_pN_per_um2 = config.number("suspension.wall_repulsion_pN_per_um2");
  settings.wall_repulsion_range_um = config.number("suspension.wall_repulsion_range_um");
  settings.wall_law = cases::wall_law_named(config.string("suspension.wall_law"));
  settings.contact = {config.number("suspension.contact_force_pN"),
                      config.number("suspension.contact_range_um"),
                      contact::contact_law_named(config.string("suspension.contact_law")),
                      config.number("suspension.contact_force_cap_pN")};
  settings.packing.cell_gap_um = settings.contact.range_um;
  settings.packing.wall_gap_um = settings.wall_repulsion_range_um;
  settings.packing.seed = static_cast<unsigned>(config.integer("suspension.seed"));
  settings.packing.orientation = config.string("suspension.packing_orientation") == "axial"
                                     ? cases::PackingOrientation::axial
                                     : cases::PackingOrientation::random;
  settings.packing.max_iterations =
      static_cast<std::size_t>(config.integer("suspension.packing_max_iterations"));
  settings.packing.scale = config.number("suspension.packing_scale");
  settings.growth_time_s = config.number("suspension.growth_time_s");
}

}  // namespace

cases::SuspensionSettings suspension_settings_from(const config::Config& config) {
  cases::SuspensionSettings settings;
  settings.tube_diameter_um = config.number("suspension.tube_diameter_um");
  settings.tube_length_um = config.number("suspension.tube_length_um");
  settings.plasma_mean_velocity_m_per_s = config.number("suspension.plasma_mean_velocity_m_per_s");
  settings.duration_s = config.number("suspension.duration_s");
  settings.sample_interval_s = config.number("suspension.sample_interval_s");
  settings.profile_rings = static_cast<std::size_t>(config.integer("suspension.profile_rings"));
  read_interactions(config, settings);
  settings.fluid_tolerance = config.number("capillary.fluid_tolerance");
  settings.fluid_max_steps = static_cast<std::size_t>(config.integer("capillary.fluid_max_steps"));
  return settings;
}

cases::ShearedSuspensionSettings sheared_suspension_settings_from(const config::Config& config,
                                                                  double diameter_um,
                                                                  double simulated_rate_per_s) {
  cases::ShearedSuspensionSettings settings;
  settings.gap_um = config.number("shear.gap_diameters") * diameter_um;
  settings.length_um = config.number("shear.width_diameters") * diameter_um;
  settings.width_um = settings.length_um;
  settings.shear_rate_per_s = simulated_rate_per_s;
  settings.strain = config.number("suspension.strain");
  settings.sample_interval_strain = config.number("suspension.sample_interval_strain");
  read_interactions(config, settings);
  return settings;
}

SuspensionCompression sheared_suspension_compression_from(const config::Config& config,
                                                          double rate_per_s, double diameter_um) {
  SuspensionCompression compression;
  const double radius_m = 0.5e-6 * diameter_um;
  compression.physical_reynolds_number =
      rate_per_s * radius_m * radius_m /
      config.number("physics.plasma_kinematic_viscosity_m2_per_s");
  compression.simulated_reynolds_number = compression.physical_reynolds_number;
  if (!config.boolean("shear.viscosity_scaling")) return compression;
  const double limit = config.number("shear.max_reynolds_number");
  compression.factor = low_reynolds_compression_factor(compression.physical_reynolds_number, limit);
  if (compression.factor != 1.0) compression.simulated_reynolds_number = limit;
  return compression;
}

std::optional<std::string> contact_range_notice(const config::Config& config) {
  const double range_um = config.number("suspension.contact_range_um");
  const double spacing_um = config.number("lattice.spacing_um");
  const auto& kernel = ibm::find_delta_kernel(config.string("ibm.kernel"));
  const double width_um = kernel.support_width * spacing_um;
  if (!(range_um < width_um)) return std::nullopt;
  return "suspension.contact_range_um " + format_number(range_um) + " um is shorter than the " +
         config.string("ibm.kernel") + " kernel's width (" + std::to_string(kernel.support_width) +
         " x " + format_number(spacing_um) +
         " um): membranes held closer than that are hardly parted by the fluid, and the push "
         "can fold a membrane or let it through (docs/validation.md, Suspensions)";
}

std::string placed_kind_name(const config::CellPlacement& cell) {
  return cell.mesh_file.empty() ? cell.morphology : cell.morphology + " (" + cell.mesh_file + ")";
}

std::vector<cases::SuspensionMorphology> suspension_morphologies_from(
    const config::ConfigRequest& request, const SuspensionMix& mix, double compression_factor,
    std::vector<std::string>* import_notices) {
  std::vector<cases::SuspensionMorphology> morphologies;
  for (std::size_t m = 0; m < mix.names.size(); ++m) {
    auto own = request;
    own.morphology = mix.morphologies.at(m);
    auto config = config::resolve_config(own);
    config = config.with("membrane.viscosity_Pa_s_um",
                         config.number("membrane.viscosity_Pa_s_um") / compression_factor);
    if (!mix.mesh_files.at(m).empty()) {
      config = config.with("mesh.file", mix.mesh_files[m]);
    }
    auto cell = cell_mesh_from(config);
    if (import_notices) {
      for (const auto& notice : cell.notices)
        import_notices->push_back(mix.names[m] + ": " + notice);
    }
    auto parameters = cell_membrane_parameters_from(config, cell.mesh);
    morphologies.push_back({mix.names[m], std::move(cell.mesh), std::move(parameters)});
  }
  return morphologies;
}

SuspensionCompression suspension_compression_from(const config::Config& config) {
  SuspensionCompression compression;
  const double velocity = config.number("suspension.plasma_mean_velocity_m_per_s");
  const double viscosity = config.number("physics.plasma_kinematic_viscosity_m2_per_s");
  compression.physical_reynolds_number =
      velocity * config.number("suspension.tube_diameter_um") * 1e-6 / viscosity;
  compression.simulated_reynolds_number = compression.physical_reynolds_number;
  const double limit = config.number("suspension.max_reynolds_number");
  compression.factor = low_reynolds_compression_factor(compression.physical_reynolds_number, limit);
  if (compression.factor == 1.0) return compression;
  compression.simulated_reynolds_number = limit;
  return compression;
}

config::Config compressed_suspension_config(const config::Config& config, double s) {
  if (s == 1.0) return config;
  auto compressed =
      config
          .with("physics.plasma_kinematic_viscosity_m2_per_s",
                config.number("physics.plasma_kinematic_viscosity_m2_per_s") / s)
          .with("suspension.plasma_mean_velocity_m_per_s",
                config.number("suspension.plasma_mean_velocity_m_per_s") * s)
          .with("membrane.viscosity_Pa_s_um", config.number("membrane.viscosity_Pa_s_um") / s);
  for (const char* time :
       {"suspension.duration_s", "suspension.sample_interval_s", "suspension.growth_time_s",
        "output.membrane_interval_s", "output.fluid_interval_s"}) {
    compressed = compressed.with(time, config.number(time) / s);
  }
  return compressed;
}

void to_physical_units(cases::SuspensionRun& run, double s) {
  if (s == 1.0) return;
  for (auto& sample : run.samples) {
    sample.time_s *= s;
    sample.flow_rate_um3_per_s /= s;
  }
  for (auto& sample : run.cell_samples) {
    sample.time_s *= s;
    sample.velocity_x_m_per_s /= s;
  }
  run.time_s *= s;
  run.plasma_flow_rate_um3_per_s /= s;
  run.pseudo_shear_rate_per_s /= s;
  // G = 8 mu U / R^2 with mu / s and U s: unchanged.
  const std::string note =
      " (times in this message are simulated ones: physical = " + format_number(s) +
      " x simulated, suspension.max_reynolds_number)";
  if (!run.stop_reason.empty()) run.stop_reason += note;
  if (!run.failure.empty()) run.failure += note;
}

}  // namespace rbcsim::setup
