#include "cases/suspension_output.hpp"

#include "cases/json_values.hpp"

namespace rbcsim::cases {

std::vector<std::string> suspension_table_columns() {
  return {"time_s",
          "flow_rate_um3_per_s",
          "relative_apparent_viscosity",
          "tube_hematocrit",
          "discharge_hematocrit",
          "cell_free_layer_um",
          "populated_bin_fraction",
          "contact_pairs",
          "close_contact_pairs",
          "pierced_cells"};
}

std::vector<double> suspension_table_row(const SuspensionSample& sample) {
  return {sample.time_s,
          sample.flow_rate_um3_per_s,
          sample.relative_apparent_viscosity,
          sample.tube_hematocrit,
          sample.discharge_hematocrit,
          sample.cell_free_layer_um,
          sample.populated_bin_fraction,
          static_cast<double>(sample.contact_pairs),
          static_cast<double>(sample.close_contact_pairs),
          static_cast<double>(sample.pierced_cells)};
}

std::vector<std::string> suspension_cell_table_columns() {
  return {"time_s",           "cell_id",       "morphology_index",   "centroid_x_um",
          "centroid_y_um",    "centroid_z_um", "radial_position_um", "velocity_x_m_per_s",
          "deformation_index"};
}

std::vector<double> suspension_cell_table_row(const SuspensionCellSample& sample,
                                              std::span<const std::size_t> cell_morphologies) {
  return {sample.time_s,
          static_cast<double>(sample.cell),
          static_cast<double>(cell_morphologies[sample.cell]),
          sample.centroid_um.x(),
          sample.centroid_um.y(),
          sample.centroid_um.z(),
          sample.radial_position_um,
          sample.velocity_x_m_per_s,
          sample.deformation_index};
}

std::vector<std::string> hematocrit_profile_columns() {
  return {"time_s", "ring", "inner_radius_um", "outer_radius_um", "volume_fraction"};
}

std::vector<std::vector<double>> hematocrit_profile_rows(const SuspensionSample& sample,
                                                         const SuspensionSettings& settings) {
  const auto& profile = sample.volume_fraction_by_ring;
  const double width_um = 0.5 * settings.tube_diameter_um / static_cast<double>(profile.size());
  std::vector<std::vector<double>> rows;
  for (std::size_t ring = 0; ring < profile.size(); ++ring) {
    const double inner_um = width_um * static_cast<double>(ring);
    rows.push_back(
        {sample.time_s, static_cast<double>(ring), inner_um, inner_um + width_um, profile[ring]});
  }
  return rows;
}

nlohmann::ordered_json hematocrit_profile_section(const SuspensionSettings& settings,
                                                  std::span<const double> volume_fraction) {
  const double width_um =
      0.5 * settings.tube_diameter_um / static_cast<double>(settings.profile_rings);
  std::vector<double> inner_um, outer_um;
  for (std::size_t ring = 0; ring < settings.profile_rings; ++ring) {
    inner_um.push_back(width_um * static_cast<double>(ring));
    outer_um.push_back(width_um * static_cast<double>(ring + 1));
  }
  return {{"ring_inner_radius_um", inner_um},
          {"ring_outer_radius_um", outer_um},
          {"volume_fraction", std::vector<double>(volume_fraction.begin(), volume_fraction.end())}};
}

namespace {

// Per morphology, where its cells were over the averaging window (null for a kind with none).
nlohmann::ordered_json morphology_section(std::span<const std::string> morphology_names,
                                          std::span<const MorphologyAverages> averages) {
  nlohmann::ordered_json section = nlohmann::ordered_json::object();
  for (std::size_t m = 0; m < morphology_names.size(); ++m) {
    const auto* kind = m < averages.size() ? &averages[m] : nullptr;
    if (kind == nullptr || kind->cell_samples == 0) {
      section[morphology_names[m]] = nullptr;
      continue;
    }
    section[morphology_names[m]] = {{"cell_samples", kind->cell_samples},
                                    {"radial_position_um", kind->radial_position_um},
                                    {"velocity_x_m_per_s", kind->velocity_x_m_per_s},
                                    {"deformation_index", kind->deformation_index}};
  }
  return section;
}

}  // namespace

nlohmann::ordered_json suspension_result_section(std::span<const std::string> morphology_names,
                                                 const SuspensionSettings& settings,
                                                 const SuspensionRun& run) {
  nlohmann::ordered_json counts = nlohmann::ordered_json::object();
  for (const auto& name : morphology_names) counts[name] = 0;
  for (const std::size_t m : run.cell_morphologies) {
    counts[morphology_names[m]] = counts[morphology_names[m]].get<int>() + 1;
  }
  const auto& a = run.averages;
  const double travel_um = mean_cell_travel_um(run.cell_samples);
  std::size_t capped = 0;
  for (const std::size_t steps : run.force_capped_steps) capped += steps;
  return {
      {"geometry", "tube"},
      {"tube_diameter_um", settings.tube_diameter_um},
      {"tube_length_um", settings.tube_length_um},
      {"cells", run.cell_morphologies.size()},
      {"cells_per_morphology", counts},
      {"morphologies", morphology_names},
      {"packed_hematocrit", run.packed_hematocrit},
      {"packing_iterations", run.packing_iterations},
      {"packing_scale", settings.packing.scale},
      {"growth_time_s", settings.packing.scale < 1.0 ? settings.growth_time_s : 0.0},
      {"plasma_mean_velocity_m_per_s", settings.plasma_mean_velocity_m_per_s},
      {"pseudo_shear_rate_per_s", run.pseudo_shear_rate_per_s},
      {"pressure_gradient_Pa_per_m", run.pressure_gradient_Pa_per_m},
      {"plasma_flow_rate_um3_per_s", run.plasma_flow_rate_um3_per_s},
      {"averaging_samples", a.samples},
      {"relative_apparent_viscosity", a.relative_apparent_viscosity},
      {"relative_apparent_viscosity_sd", a.relative_apparent_viscosity_sd},
      {"tube_hematocrit", a.tube_hematocrit},
      {"discharge_hematocrit", a.discharge_hematocrit},
      {"tube_to_discharge_hematocrit",
       a.discharge_hematocrit > 0.0 ? a.tube_hematocrit / a.discharge_hematocrit : 0.0},
      {"cell_free_layer_um", a.cell_free_layer_um},
      {"hematocrit_profile", hematocrit_profile_section(settings, a.volume_fraction_by_ring)},
      {"by_morphology", morphology_section(morphology_names, a.by_morphology)},
      {"contact_law", contact::contact_law_name(settings.contact.law)},
      {"contact_force_pN", settings.contact.force_at_contact_pN},
      {"contact_range_um", settings.contact.range_um},
      {"contact_force_cap_pN", settings.contact.force_cap_pN},
      {"close_contact_steps", run.close_contact_steps},
      {"capped_contact_steps", run.capped_contact_steps},
      {"samples_with_pierced_cells", run.samples_with_pierced_cells},
      {"force_capped_steps", capped},
      {"sub_spacing_drag", sub_spacing_drag_json(run.sub_spacing_drag)},
      {"fluid_settling_steps", run.fluid_settling_steps},
      {"steps", run.steps},
      {"time_s", run.time_s},
      {"cell_travel_um", travel_um},
      {"cell_travel_tube_diameters", travel_um / settings.tube_diameter_um},
      {"stop_reason", run.stop_reason},
      {"failure", run.failure},
  };
}

}  // namespace rbcsim::cases
