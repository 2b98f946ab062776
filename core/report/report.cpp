#include "report/report.hpp"

#include <algorithm>
#include <tuple>

#include "common/errors.hpp"
#include "io/atomic_file.hpp"
#include "report/sections.hpp"

namespace rbcsim::report {
namespace {

// Position of a command in the report: the experiments in their table's order, then the rest.
std::size_t command_rank(const std::string& command) {
  const auto sections = experiment_sections();
  const auto found = std::find_if(sections.begin(), sections.end(), [&command](const auto& entry) {
    return entry.command == command;
  });
  return static_cast<std::size_t>(found - sections.begin());
}

bool report_order(const RunDirectory& a, const RunDirectory& b) {
  const auto key = [](const RunDirectory& run) {
    return std::make_tuple(command_rank(run.command), std::cref(run.command),
                           std::cref(run.morphology), std::cref(run.terms),
                           run.directory.generic_string());
  };
  return key(a) < key(b);
}

RunList runs_of(const std::vector<RunDirectory>& runs, const std::string& command) {
  RunList selected;
  for (const auto& run : runs) {
    if (run.command == command) selected.push_back(&run);
  }
  return selected;
}

std::vector<Section> build_sections(const std::vector<RunDirectory>& runs) {
  RunList all;
  for (const auto& run : runs) all.push_back(&run);
  // The verdict first, then the experiments in the paper's order (Figs. 8, 9-11, 13, 18), then
  // the details of every run.
  std::vector<Section> sections;
  for (const auto& experiment : experiment_sections()) {
    const auto selected = runs_of(runs, std::string(experiment.command));
    if (!selected.empty()) sections.push_back(experiment.build(selected));
  }
  std::vector<std::string> other_commands;
  for (const auto& run : runs) {
    const bool has_section = command_rank(run.command) < experiment_sections().size();
    if (!has_section && std::find(other_commands.begin(), other_commands.end(), run.command) ==
                            other_commands.end()) {
      other_commands.push_back(run.command);
    }
  }
  for (std::size_t i = 0; i < other_commands.size(); ++i) {
    sections.push_back(
        build_other_section(other_commands[i], i + 1, runs_of(runs, other_commands[i])));
  }
  sections.insert(sections.begin(), build_verdict_section(all, sections));
  sections.push_back(build_runs_section(all));
  return sections;
}

}  // namespace

std::vector<RunDirectory> read_run_directories(
    const std::vector<std::filesystem::path>& directories) {
  std::vector<RunDirectory> runs;
  for (const auto& directory : directories) runs.push_back(read_run_directory(directory));
  return runs;
}

ReportDocuments build_report(std::vector<RunDirectory> runs) {
  std::sort(runs.begin(), runs.end(), report_order);
  const auto sections = build_sections(runs);
  const std::string title = "rbcsim report";
  const std::string subtitle =
      std::to_string(runs.size()) + " run directories, report by rbcsim " + RBCSIM_VERSION + ".";
  ReportDocuments documents{render_html(title, subtitle, sections),
                            render_markdown(title, subtitle, sections),
                            {{"rbcsim_version", RBCSIM_VERSION}, {"run_count", runs.size()}}};
  for (const auto& section : sections) documents.summary[section.id] = section.summary;
  return documents;
}

std::string summary_json_text(const nlohmann::json& summary) {
  // Paths need not be UTF-8; the replacement character keeps the dump from throwing.
  return summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::vector<std::filesystem::path> write_report(const ReportDocuments& documents,
                                                const std::filesystem::path& output_directory) {
  std::error_code error;
  std::filesystem::create_directories(output_directory, error);
  if (error || !std::filesystem::is_directory(output_directory)) {
    throw InputError(output_directory.string(),
                     "cannot create the output directory" + (error ? ": " + error.message() : ""));
  }
  const std::vector<std::filesystem::path> files{output_directory / kReportFile,
                                                 output_directory / kSummaryMarkdownFile,
                                                 output_directory / kSummaryJsonFile};
  io::write_text_atomically(files[0], documents.html);
  io::write_text_atomically(files[1], documents.markdown);
  io::write_text_atomically(files[2], summary_json_text(documents.summary));
  return files;
}

}  // namespace rbcsim::report
