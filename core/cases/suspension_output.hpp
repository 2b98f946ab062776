// What a suspension run writes (the run-directory contract): suspension_timeseries.csv (the whole
// flow), cells_timeseries.csv (every cell at every sample), hematocrit_profile.csv (the cells'
// volume fraction in rings about the axis at every sample) and the "suspension" object of
// result.json (schemas/result.schema.json).
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "cases/suspension_case.hpp"

namespace rbcsim::cases {

std::vector<std::string> suspension_table_columns();
std::vector<double> suspension_table_row(const SuspensionSample& sample);
std::vector<std::string> suspension_cell_table_columns();
std::vector<double> suspension_cell_table_row(const SuspensionCellSample& sample,
                                              std::span<const std::size_t> cell_morphologies);

// hematocrit_profile.csv: one row per sample and ring (time_s, ring, inner_radius_um,
// outer_radius_um, volume_fraction); result.json's "hematocrit_profile" (the averaged one).
std::vector<std::string> hematocrit_profile_columns();
std::vector<std::vector<double>> hematocrit_profile_rows(const SuspensionSample& sample,
                                                         const SuspensionSettings& settings);
nlohmann::ordered_json hematocrit_profile_section(const SuspensionSettings& settings,
                                                  std::span<const double> volume_fraction);

nlohmann::ordered_json suspension_result_section(std::span<const std::string> morphology_names,
                                                 const SuspensionSettings& settings,
                                                 const SuspensionRun& run);

}  // namespace rbcsim::cases
