// One run directory as `rbcsim report` reads it (the run-directory contract: config.json,
// result.json and the command's CSV files), and the way runs are grouped: by command, then by
// morphology, then by the enabled membrane force terms (config.json membrane.forces).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/csv_table.hpp"
#include "report/json_field.hpp"

namespace rbcsim::report {

struct RunDirectory {
  std::filesystem::path directory;
  std::string command;     // result.json "command": calibrate, stretch, shear, capillary, ...;
                           // "suspension" for a capillary run with a "suspension" object
  std::string morphology;  // result.json "morphology"
  std::string preset;      // config.json "preset"; "-" for runs older than presets
  std::string status;      // result.json "status": "ok", "failed" or "interrupted"
  std::vector<std::string> forces;   // config.json membrane.forces, the enabled terms
  std::string terms;                 // describe_terms(forces)
  std::vector<std::string> notices;  // config.json run.notices: told when the run started
  nlohmann::json config;             // config.json as written
  nlohmann::json result;             // result.json as written

  bool succeeded() const { return status == "ok"; }
  // Checked reads of the two documents; diagnostics name the file.
  JsonField config_field() const;
  JsonField result_field() const;
  // The command's own object of result.json ("stretch": {...} for a stretch run).
  JsonField section() const { return result_field().at(command); }
  // A CSV file of the run directory, e.g. "capillary_timeseries.csv".
  io::CsvTable csv(const std::string& file_name) const {
    return io::read_csv_file(directory / file_name);
  }
};

// Reads config.json and result.json of `directory` and checks the members every run has
// (command, morphology, status, version, wall_time_s, threads, headline, membrane.forces). Throws
// InputError naming the directory or the file and the JSON path of the problem.
RunDirectory read_run_directory(const std::filesystem::path& directory);

// The enabled membrane terms in words, relative to the full table of terms: "all six", "without
// area_difference and total_curvature", or the enabled names themselves when they are not a
// subset of the table (an unknown name).
std::string describe_terms(const std::vector<std::string>& enabled);

}  // namespace rbcsim::report
