#include "cases/shear_output.hpp"

#include <cmath>

namespace rbcsim::cases {
namespace {

nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json rate_entry(const ShearPoint& point) {
  const auto& plan = point.plan;
  nlohmann::ordered_json entry = {
      {"shear_rate_per_s", plan.shear_rate_per_s},
      {"length_um", number_or_null(point.shape.length_um)},
      {"breadth_um", number_or_null(point.shape.breadth_um)},
      {"deformation_index", number_or_null(point.shape.deformation_index)},
      {"inclination_deg", number_or_null(point.shape.inclination_deg)},
      {"tank_treading_hz", number_or_null(point.tank_treading_hz)},
      {"smoothness_rad", number_or_null(point.smoothness_rad)},
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
      {"stop_reason", point.stop_reason},
      {"wall_time_s", point.wall_time_s}};
  if (!point.failure.empty()) entry["failure"] = point.failure;
  return entry;
}

}  // namespace

std::vector<std::string> shear_table_columns() {
  return {"shear_rate_per_s",
          "length_um",
          "breadth_um",
          "deformation_index",
          "inclination_deg",
          "tank_treading_hz",
          "smoothness_rad",
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
          point.shape.breadth_um,
          point.shape.deformation_index,
          point.shape.inclination_deg,
          point.tank_treading_hz,
          point.smoothness_rad,
          point.steady ? 1.0 : 0.0,
          plan.simulated_shear_rate_per_s,
          plan.simulated_kinematic_viscosity_m2_per_s,
          plan.reynolds_number,
          plan.capillary_number,
          point.strain,
          point.time_s,
          static_cast<double>(point.steps)};
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
