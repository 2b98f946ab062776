// What a shear run writes (the run-directory contract): the rows of shear.csv and the "shear"
// object of result.json (schemas/result.schema.json). The shapes are the coupled loop's membrane
// snapshots (coupling/snapshot.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "cases/shear_case.hpp"

namespace rbcsim::cases {

std::vector<std::string> shear_table_columns();
std::vector<double> shear_table_row(const ShearPoint& point);

// {"boundary", "forces_terms", "viscosity_scaling", "rates": [...]}; non-finite numbers (a failed
// rate's shape, Ca without a link term) become null.
nlohmann::ordered_json shear_result_section(const ShearSettings& settings,
                                            std::span<const std::string> force_terms,
                                            std::span<const ShearPoint> points);

}  // namespace rbcsim::cases
