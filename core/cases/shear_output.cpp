#include "cases/shear_output.hpp"

#include <cmath>
#include <limits>

#include "cases/json_values.hpp"
#include "common/errors.hpp"

namespace rbcsim::cases {
namespace {

nlohmann::ordered_json rate_entry(const ShearPoint& point) {
  const auto& plan = point.plan;
  nlohmann::ordered_json entry = {
      {"shear_rate_per_s", plan.shear_rate_per_s},
      {"length_um", number_or_null(point.shape.length_um)},
      {"length_swing_um", number_or_null(point.length_swing_um)},
      {"window_strain", point.window_strain},
      {"breadth_um", number_or_null(point.shape.breadth_um)},
      {"deformation_index", number_or_null(point.shape.deformation_index)},
      {"inclination_deg", number_or_null(point.shape.inclination_deg)},
      {"tank_treading_hz", number_or_null(point.tank_treading_hz)},
      {"smoothness_rad", number_or_null(point.smoothness_rad)},
      {"roughness_rad", number_or_null(point.roughness_rad)},
      {"area_change", number_or_null(point.area_strain.total_relative_change)},
      {"max_triangle_area_deviation", number_or_null(point.area_strain.max_abs_triangle_deviation)},
      {"steady", point.steady},
      {"simulated_shear_rate_per_s", plan.simulated_shear_rate_per_s},
      {"simulated_kinematic_viscosity_m2_per_s", plan.simulated_kinematic_viscosity_m2_per_s},
      {"viscosity_scale", plan.viscosity_scale},
      {"reynolds_number", plan.reynolds_number},
      {"capillary_number", number_or_null(plan.capillary_number)},
      {"strain", point.strain},
      {"time_s", point.time_s},
      {"steps", point.steps},
      {"force_cap_steps", point.force_cap_steps},
      {"sub_spacing_drag", sub_spacing_drag_json(point.sub_spacing_drag)},
      {"stop_reason", point.stop_reason},
      {"wall_time_s", point.wall_time_s}};
  if (!point.failure.empty()) entry["failure"] = point.failure;
  return entry;
}

}  // namespace

nlohmann::ordered_json shear_point_record(const ShearPoint& point) {
  auto record = rate_entry(point);
  record["strain_rate_lu"] = point.plan.strain_rate_lu;
  return record;
}

ShearPoint shear_point_from_record(const nlohmann::json& record, const std::string& source) {
  const auto number = [&](const char* key) { return record_number(record, key, source); };
  const auto count = [&](const char* key) { return static_cast<std::size_t>(number(key)); };
  ShearPoint point;
  auto& plan = point.plan;
  plan.shear_rate_per_s = number("shear_rate_per_s");
  plan.simulated_shear_rate_per_s = number("simulated_shear_rate_per_s");
  plan.simulated_kinematic_viscosity_m2_per_s = number("simulated_kinematic_viscosity_m2_per_s");
  plan.viscosity_scale = number("viscosity_scale");
  plan.reynolds_number = number("reynolds_number");
  plan.capillary_number = number("capillary_number");
  plan.strain_rate_lu = number("strain_rate_lu");
  point.shape = {number("length_um"), number("breadth_um"), number("deformation_index"),
                 number("inclination_deg")};
  point.length_swing_um = number("length_swing_um");
  point.window_strain = number("window_strain");
  point.tank_treading_hz = number("tank_treading_hz");
  point.smoothness_rad = number("smoothness_rad");
  point.roughness_rad = number("roughness_rad");
  point.area_strain = {number("area_change"), number("max_triangle_area_deviation")};
  point.steady = record.value("steady", false);
  point.strain = number("strain");
  point.time_s = number("time_s");
  point.steps = count("steps");
  point.force_cap_steps = count("force_cap_steps");
  point.sub_spacing_drag =
      sub_spacing_drag_from_json(record.value("sub_spacing_drag", nullptr), source);
  point.stop_reason = record.value("stop_reason", std::string());
  point.wall_time_s = number("wall_time_s");
  return point;
}

std::vector<std::string> shear_table_columns() {
  return {"shear_rate_per_s",
          "length_um",
          "length_swing_um",
          "window_strain",
          "breadth_um",
          "deformation_index",
          "inclination_deg",
          "tank_treading_hz",
          "smoothness_rad",
          "roughness_rad",
          "area_change",
          "max_triangle_area_deviation",
          "steady",
          "simulated_shear_rate_per_s",
          "simulated_kinematic_viscosity_m2_per_s",
          "reynolds_number",
          "capillary_number",
          "strain",
          "time_s",
          "steps"};
}

std::vector<double> shear_table_row(const ShearPoint& point) {
  const auto& plan = point.plan;
  return {plan.shear_rate_per_s,
          point.shape.length_um,
          point.length_swing_um,
          point.window_strain,
          point.shape.breadth_um,
          point.shape.deformation_index,
          point.shape.inclination_deg,
          point.tank_treading_hz,
          point.smoothness_rad,
          point.roughness_rad,
          point.area_strain.total_relative_change,
          point.area_strain.max_abs_triangle_deviation,
          point.steady ? 1.0 : 0.0,
          plan.simulated_shear_rate_per_s,
          plan.simulated_kinematic_viscosity_m2_per_s,
          plan.reynolds_number,
          plan.capillary_number,
          point.strain,
          point.time_s,
          static_cast<double>(point.steps)};
}

std::vector<std::string> shear_history_columns() {
  return {"strain", "length_um", "breadth_um", "deformation_index", "inclination_deg"};
}

std::vector<std::vector<double>> shear_history_rows(const ShearPoint& point) {
  std::vector<std::vector<double>> rows;
  for (const auto& sample : point.history) {
    const auto& shape = sample.shape;
    rows.push_back({sample.strain, shape.length_um, shape.breadth_um, shape.deformation_index,
                    shape.inclination_deg});
  }
  return rows;
}

nlohmann::ordered_json shear_result_section(const ShearSettings& settings,
                                            std::span<const std::string> force_terms,
                                            std::span<const ShearPoint> points) {
  nlohmann::ordered_json rates = nlohmann::ordered_json::array();
  for (const auto& point : points) rates.push_back(rate_entry(point));
  return {{"boundary", settings.boundary},
          {"forces_terms", force_terms},
          {"viscosity_scaling", settings.viscosity_scaling},
          {"rates", rates}};
}

}  // namespace rbcsim::cases
