// What a suspension run writes (the run-directory contract): suspension_timeseries.csv (the whole
// flow), cells_timeseries.csv (every cell at every sample) and the "suspension" object of
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

nlohmann::ordered_json suspension_result_section(std::span<const std::string> morphology_names,
                                                 const SuspensionSettings& settings,
                                                 const SuspensionRun& run);

}  // namespace rbcsim::cases
