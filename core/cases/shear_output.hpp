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

// <run dir>/rate_<i>/history.csv: the shape against strain (ShearPoint::history), one row per
// sample.
std::vector<std::string> shear_history_columns();
std::vector<std::vector<double>> shear_history_rows(const ShearPoint& point);

// {"boundary", "forces_terms", "viscosity_scaling", "rates": [...]}; non-finite numbers (a failed
// rate's shape, Ca without a link term) become null.
nlohmann::ordered_json shear_result_section(const ShearSettings& settings,
                                            std::span<const std::string> force_terms,
                                            std::span<const ShearPoint> points);

// A finished rate's point as JSON whose numbers read back bit for bit (nlohmann writes the
// shortest text that round-trips): <run dir>/rate_<i>/point.json, the rates a resumed sweep
// does not run again. shear_point_from_record throws InputError naming `source` for a record
// without one of the numbers.
nlohmann::ordered_json shear_point_record(const ShearPoint& point);
ShearPoint shear_point_from_record(const nlohmann::json& record, const std::string& source);

}  // namespace rbcsim::cases
