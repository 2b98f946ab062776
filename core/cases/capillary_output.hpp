// What a capillary run writes (the run-directory contract): the rows of capillary_timeseries.csv
// and the "capillary" object of result.json (schemas/result.schema.json).
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cases/capillary_case.hpp"

namespace rbcsim::cases {

std::vector<std::string> capillary_table_columns();
std::vector<double> capillary_table_row(const CapillarySample& sample);

// What the run was, beside what it measured.
struct CapillaryDescription {
  std::string geometry;  // the preset's name, or the wall file
  std::string cell_axis;
  std::vector<std::string> force_terms;
};

nlohmann::ordered_json capillary_result_section(const CapillaryDescription& description,
                                                const CapillaryRun& run);

}  // namespace rbcsim::cases
