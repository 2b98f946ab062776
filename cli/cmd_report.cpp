// rbcsim report RUN_DIR... [-o OUTPUT_DIR] [--json]: one self-contained HTML page of plots and
// tables, summary.md and summary.json from the run directories of the experiment commands.
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include "command_registry.hpp"
#include "report/report.hpp"

namespace rbcsim::cli::report_command {
namespace {

struct ReportOptions {
  std::vector<std::filesystem::path> run_directories;
  std::filesystem::path output_directory = "report";
  bool json = false;
};

void run_report(const ReportOptions& options) {
  const auto documents =
      report::build_report(report::read_run_directories(options.run_directories));
  const auto files = report::write_report(documents, options.output_directory);
  if (options.json) {
    std::cout << report::summary_json_text(documents.summary);
    return;
  }
  for (const auto& file : files) std::cout << "wrote " << file.string() << '\n';
}

void attach_report_command(CLI::App& application) {
  auto* command = application.add_subcommand(
      "report",
      "HTML report of run directories (plots against reference data, tables) + summary.md/.json");
  auto options = std::make_shared<ReportOptions>();
  command
      ->add_option("RUN_DIR", options->run_directories,
                   "Run directories written by calibrate, stretch, shear or capillary")
      ->required();
  command
      ->add_option("-o,--output", options->output_directory,
                   "Directory for report.html, summary.md and summary.json")
      ->default_str("report");
  command->add_flag("--json", options->json, "Print summary.json on stdout");
  command->callback([options] { run_report(*options); });
}

const bool registered = register_command({"report", 80, attach_report_command});

}  // namespace
}  // namespace rbcsim::cli::report_command
