// What a stretch run writes (the run-directory contract): one VTK PolyData shape per force, the
// rows of stretch.csv, and the "stretch" object of result.json (schemas/result.schema.json); and
// the rows of the calibrate stretch fit's stretch_fit.csv.
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

// {"mode", "forces_terms", "points": [...], "comparison": {...}}.
nlohmann::ordered_json stretch_result_section(std::string_view mode,
                                              std::span<const std::string> force_terms,
                                              std::span<const StretchPoint> points,
                                              const StretchComparison& comparison);

}  // namespace rbcsim::cases
