// `rbcsim report RUN_DIR...`: the public entry point of the report module. Reads run
// directories (the run-directory contract), builds one self-contained HTML page (inline CSS and
// SVG, no JavaScript, XHTML-compatible), summary.md (the headline numbers as Markdown tables)
// and summary.json (machine-readable). Same inputs, same bytes: nothing depends on the clock, the
// locale or the order of the arguments.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/run_directory.hpp"

namespace rbcsim::report {

struct ReportDocuments {
  std::string html;
  std::string markdown;
  nlohmann::json summary;
};

// Reads every directory; the first bad one throws InputError naming it (or its file).
std::vector<RunDirectory> read_run_directories(
    const std::vector<std::filesystem::path>& directories);

// The report of `runs` in the report's order: by command (calibrate, stretch, shear, capillary,
// then others by name), morphology, membrane terms and directory. Throws InputError when a
// command's own data (result.json section, CSV file) is missing or malformed.
ReportDocuments build_report(std::vector<RunDirectory> runs);

// The file names below the output directory.
inline constexpr std::string_view kReportFile = "report.html";
inline constexpr std::string_view kSummaryMarkdownFile = "summary.md";
inline constexpr std::string_view kSummaryJsonFile = "summary.json";

// Writes the three files into `output_directory` (created if missing), each atomically, and
// returns their paths. A directory that cannot be created is bad input (InputError).
std::vector<std::filesystem::path> write_report(const ReportDocuments& documents,
                                                const std::filesystem::path& output_directory);

// summary.json's text: the summary indented by two spaces, with a final newline.
std::string summary_json_text(const nlohmann::json& summary);

}  // namespace rbcsim::report
