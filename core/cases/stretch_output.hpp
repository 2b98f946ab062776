// What a stretch run writes (the run-directory contract): one VTK PolyData shape per force, the
// rows of stretch.csv, and the "stretch" object of result.json (schemas/result.schema.json); and
// the rows of the calibrate stretch fit's stretch_fit.csv and its comparison with the data.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "cases/stretch_case.hpp"
#include "cases/stretch_fit.hpp"
#include "cases/stretch_reference.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

// The shape of one force with per-vertex arrays: membrane_force_pN (the sum of the terms),
// force_<term>_pN for each enabled term, and tweezer_force_pN. Atomic.
void write_stretch_shape(const std::filesystem::path& path,
                         std::span<const mesh::Triangle> triangles, const StretchState& state);

std::vector<std::string> stretch_table_columns();
std::vector<double> stretch_table_row(const StretchPoint& point);

// One row per curve of the fit, in the order run: how the search went. A failed curve's misfit is
// inf and its RMS deviations nan.
std::vector<std::string> stretch_fit_table_columns();
std::vector<double> stretch_fit_table_row(const StretchFitEvaluation& curve);

// A curve against Mills et al. (2004): {"reference", "rms_axial_um", "rms_transverse_um" (null
// when no reference force is in range), "inside_error_bars", "axial_inside_error_bar",
// "transverse_inside_error_bar", "point_count"}; the stretch's and the stretch fit's.
nlohmann::ordered_json mills_comparison_json(const StretchComparison& comparison);

// How a fluid-mode force started (StretchPoint::warm_start): "warm", or "ramped" with the reason.
std::string_view warm_start_name(WarmStart start);

// {"mode", "forces_terms", "points": [...], "comparison": mills_comparison_json}, and with
// stretch.fluid.warm_start each point's "start" and the count of "warm_start_fallbacks".
nlohmann::ordered_json stretch_result_section(std::string_view mode,
                                              std::span<const std::string> force_terms,
                                              std::span<const StretchPoint> points,
                                              const StretchComparison& comparison);

}  // namespace rbcsim::cases
