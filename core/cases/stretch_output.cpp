#include "cases/stretch_output.hpp"

#include <algorithm>
#include <limits>

#include "cases/json_values.hpp"
#include "io/vtk_polydata.hpp"

namespace rbcsim::cases {

void write_stretch_shape(const std::filesystem::path& path,
                         std::span<const mesh::Triangle> triangles, const StretchState& state) {
  std::vector<io::PointDataArray> arrays;
  if (state.membrane_forces) {
    arrays.push_back(io::vector_point_array("membrane_force_pN", state.membrane_forces->total_pN));
    for (const auto& term : state.membrane_forces->terms) {
      arrays.push_back(io::vector_point_array("force_" + term.name + "_pN", term.forces_pN));
    }
  }
  arrays.push_back(io::vector_point_array("tweezer_force_pN", state.external_forces_pN));
  io::write_vtk_polydata(path, state.positions_um, triangles, arrays);
}

std::vector<std::string> stretch_table_columns() {
  return {"force_pN",   "axial_um",          "transverse_um",   "converged",
          "iterations", "residual_force_pN", "force_cap_hits",  "wall_time_s",
          "steps",      "simulated_time_s",  "max_mach_number", "max_reynolds_number"};
}

std::vector<double> stretch_table_row(const StretchPoint& point) {
  return {point.force_pN,
          point.axial_um,
          point.transverse_um,
          point.converged ? 1.0 : 0.0,
          static_cast<double>(point.iterations),
          point.residual_force_pN,
          static_cast<double>(point.force_cap_hits),
          point.wall_time_s,
          static_cast<double>(point.steps),
          point.time_s,
          point.max_mach_number,
          point.max_reynolds_number};
}

std::vector<std::string> stretch_fit_table_columns() {
  return {"k_link_kBT",        "misfit",     "rms_axial_um", "rms_transverse_um",
          "inside_error_bars", "wall_time_s"};
}

std::vector<double> stretch_fit_table_row(const StretchFitEvaluation& curve) {
  constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();
  const auto& comparison = curve.comparison;
  return {curve.k_link_kBT,
          curve.misfit,
          comparison.rms_axial_um.value_or(kNotMeasured),
          comparison.rms_transverse_um.value_or(kNotMeasured),
          static_cast<double>(comparison.inside_error_bars),
          curve.wall_time_s};
}

nlohmann::ordered_json mills_comparison_json(const StretchComparison& comparison) {
  return {{"reference", "mills2004"},
          {"rms_axial_um", optional_number(comparison.rms_axial_um)},
          {"rms_transverse_um", optional_number(comparison.rms_transverse_um)},
          {"inside_error_bars", comparison.inside_error_bars},
          {"axial_inside_error_bar", comparison.axial_inside_error_bar},
          {"transverse_inside_error_bar", comparison.transverse_inside_error_bar},
          {"point_count", comparison.point_count}};
}

std::string_view warm_start_name(WarmStart start) {
  switch (start) {
    case WarmStart::off:
      return "ramped";
    case WarmStart::converged:
      return "warm";
    case WarmStart::not_converged:
      return "ramped: the warm start did not converge";
    case WarmStart::force_law_limit:
      return "ramped: the warm start met a force law's limit";
  }
  return "ramped";
}

nlohmann::ordered_json stretch_result_section(std::string_view mode,
                                              std::span<const std::string> force_terms,
                                              std::span<const StretchPoint> points,
                                              const StretchComparison& comparison) {
  auto point_list = nlohmann::ordered_json::array();
  const bool fluid = mode == "fluid";
  for (const auto& point : points) {
    nlohmann::ordered_json entry = {{"force_pN", point.force_pN},
                                    {"axial_um", point.axial_um},
                                    {"transverse_um", point.transverse_um},
                                    {"converged", point.converged}};
    if (fluid) {
      entry["steps"] = point.steps;
      entry["simulated_time_s"] = point.time_s;
      entry["max_mach_number"] = point.max_mach_number;
      entry["max_reynolds_number"] = point.max_reynolds_number;
      if (point.iterations > 0) entry["iterations"] = point.iterations;  // the warm start's
      if (point.warm_start != WarmStart::off) entry["start"] = warm_start_name(point.warm_start);
    } else {
      entry["iterations"] = point.iterations;
    }
    entry["residual_force_pN"] = point.residual_force_pN;
    entry["force_cap_hits"] = point.force_cap_hits;
    entry["wall_time_s"] = point.wall_time_s;
    point_list.push_back(entry);
  }
  nlohmann::ordered_json section = {{"mode", mode},
                                    {"forces_terms", force_terms},
                                    {"points", point_list},
                                    {"comparison", mills_comparison_json(comparison)}};
  // With stretch.fluid.warm_start: the forces that were ramped because their warm start failed.
  if (std::any_of(points.begin(), points.end(),
                  [](const auto& point) { return point.warm_start != WarmStart::off; })) {
    section["warm_start_fallbacks"] =
        std::count_if(points.begin(), points.end(), [](const auto& point) {
          return point.warm_start == WarmStart::not_converged ||
                 point.warm_start == WarmStart::force_law_limit;
        });
  }
  return section;
}

}  // namespace rbcsim::cases
