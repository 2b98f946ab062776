#include "cases/capillary_output.hpp"

#include <algorithm>
#include <optional>

#include "cases/json_values.hpp"

namespace rbcsim::cases {

std::vector<std::string> capillary_table_columns() {
  return {"time_s",
          "centroid_x_um",
          "centroid_y_um",
          "centroid_z_um",
          "velocity_x_m_per_s",
          "deformation_index",
          "length_x_um",
          "length_y_um",
          "length_z_um",
          "area_change",
          "max_triangle_area_deviation"};
}

std::vector<double> capillary_table_row(const CapillarySample& sample) {
  return {sample.time_s,
          sample.centroid_um.x(),
          sample.centroid_um.y(),
          sample.centroid_um.z(),
          sample.velocity_x_m_per_s,
          sample.deformation_index,
          sample.extents_um.x(),
          sample.extents_um.y(),
          sample.extents_um.z(),
          sample.area_strain.total_relative_change,
          sample.area_strain.max_abs_triangle_deviation};
}

namespace {

// The extremes of the sampled area strain: the largest triangle deviation and the range of the
// whole membrane's change; nulls when nothing was sampled (a run that failed before its release).
struct SampledAreaStrain {
  std::optional<double> max_triangle_deviation;
  std::optional<double> min_change;
  std::optional<double> max_change;
};

SampledAreaStrain sampled_area_strain(const std::vector<CapillarySample>& samples) {
  if (samples.empty()) return {};
  double max_triangle_deviation = 0.0;
  double min_change = samples.front().area_strain.total_relative_change;
  double max_change = min_change;
  for (const auto& sample : samples) {
    const auto& strain = sample.area_strain;
    max_triangle_deviation = std::max(max_triangle_deviation, strain.max_abs_triangle_deviation);
    min_change = std::min(min_change, strain.total_relative_change);
    max_change = std::max(max_change, strain.total_relative_change);
  }
  return {max_triangle_deviation, min_change, max_change};
}

}  // namespace

nlohmann::ordered_json capillary_result_section(const CapillaryDescription& description,
                                                const CapillaryRun& run) {
  const auto& numbers = run.numbers;
  const auto area_strain = sampled_area_strain(run.samples);
  return {
      {"geometry", description.geometry},
      {"inflow", "velocity-inlet"},
      {"cell_axis", description.cell_axis},
      {"forces_terms", description.force_terms},
      {"mean_inlet_velocity_m_per_s", numbers.mean_inlet_velocity_m_per_s},
      {"inlet_diameter_um", numbers.inlet_diameter_um},
      {"reynolds_number", numbers.reynolds_number},
      {"shear_modulus_uN_per_m", numbers.shear_modulus_N_per_m * 1e6},
      {"capillary_number", numbers.capillary_number},
      {"narrow_section_start_um", run.narrow_start_um},
      {"narrow_section_end_um", run.narrow_end_um},
      {"passed", run.passed},
      {"entry_time_s", optional_number(run.entry_time_s)},
      {"exit_time_s", optional_number(run.exit_time_s)},
      {"transit_time_s", optional_number(run.transit_time_s)},
      {"front_entry_time_s", optional_number(run.front_entry_time_s)},
      {"rear_exit_time_s", optional_number(run.rear_exit_time_s)},
      {"whole_cell_transit_time_s", optional_number(run.whole_cell_transit_time_s)},
      {"cell_diameter_um", run.cell_diameter_um},
      {"throat_diameter_um", run.throat_diameter_um},
      {"confinement", run.confinement()},
      {"initial_deformation_index", run.initial_deformation_index},
      {"peak_deformation_index", run.peak_deformation_index},
      {"peak_time_s", run.peak_time_s},
      {"peak_centroid_x_um", run.peak_centroid_x_um},
      {"final_deformation_index", run.final_deformation_index},
      {"final_centroid_x_um", run.final_centroid_x_um},
      {"max_triangle_area_deviation", optional_number(area_strain.max_triangle_deviation)},
      {"min_area_change", optional_number(area_strain.min_change)},
      {"max_area_change", optional_number(area_strain.max_change)},
      {"simulated_time_s", run.time_s},
      {"steps", run.steps},
      {"fluid_settling_steps", run.fluid_settling_steps},
      {"force_capped_steps", run.force_capped_steps},
      {"sub_spacing_drag", sub_spacing_drag_json(run.sub_spacing_drag)},
      {"stop_reason", run.stop_reason},
  };
}

}  // namespace rbcsim::cases
