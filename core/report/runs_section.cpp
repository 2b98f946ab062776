// Every run: what ran, how (membrane terms, threads, version), for how long, the notices it
// started with, and its full configuration folded under a <details>.
#include <algorithm>
#include <utility>

#include "report/markup.hpp"
#include "report/sections.hpp"

namespace rbcsim::report {
namespace {

// Every leaf of the configuration as "path.to.key": value, in the document's order.
void flatten(const nlohmann::json& node, const std::string& path, Table& table) {
  if (node.is_object() && !node.empty()) {
    for (const auto& [key, value] : node.items()) {
      flatten(value, path.empty() ? key : path + "." + key, table);
    }
    return;
  }
  // Ten significant digits: enough to reproduce the configuration, without the last-bit noise
  // of derived values (1.3200000000000003).
  constexpr int kConfigurationDigits = 10;
  table.rows.push_back({path, node.is_number_float()
                                  ? format_significant(node.get<double>(), kConfigurationDigits)
                                  : format_cell(node)});
}

std::vector<std::string> run_row(const RunDirectory& run) {
  const auto& result = run.result;
  return {run.directory.generic_string(),
          run.command,
          run.morphology,
          run.preset,
          run.terms,
          run.status,
          format_cell(result.at("wall_time_s")),
          result.at("version").get<std::string>(),
          format_cell(result.at("threads"))};
}

}  // namespace

Section build_runs_section(const RunList& runs) {
  Section section{"runs", "Runs", {}, nlohmann::json::array()};
  section.blocks.emplace_back(Paragraph{
      std::to_string(runs.size()) + " run directories. The preset and the membrane terms are "
      "config.json's (preset, membrane.forces); wall time, version and threads come from result.json; "
      "the full configuration of each run (with its start time and mesh) is folded below."});
  Table table{"Runs",
              {"run directory", "command", "morphology", "preset", "membrane terms", "status",
               "wall time (s)", "version", "threads"},
              {}};
  for (const auto* run : runs) table.rows.push_back(run_row(*run));
  section.blocks.emplace_back(std::move(table));
  // One line per distinct notice, listing the runs that got it (a main job's nine shear and
  // capillary runs often share one).
  std::vector<std::pair<std::string, std::vector<std::string>>> notices;
  for (const auto* run : runs) {
    for (const auto& notice : run->notices) {
      auto same = std::find_if(notices.begin(), notices.end(),
                               [&notice](const auto& entry) { return entry.first == notice; });
      if (same == notices.end()) same = notices.insert(notices.end(), {notice, {}});
      same->second.push_back(run->directory.generic_string());
    }
  }
  for (const auto& [notice, directories] : notices) {
    std::string who;
    for (const auto& directory : directories) who += (who.empty() ? "" : ", ") + directory;
    section.blocks.emplace_back(Paragraph{"Notice of " + who + ": " + notice + "."});
  }

  for (const auto* run : runs) {
    Table configuration{"", {"option", "value"}, {}};
    flatten(run->config, "", configuration);
    section.blocks.emplace_back(
        Details{"Configuration of " + run->directory.generic_string(), std::move(configuration)});

    auto entry = run_identity(*run);
    for (const auto* key : {"command", "status", "version", "wall_time_s", "threads", "headline"}) {
      entry[key] = run->result.at(key);
    }
    entry["notices"] = run->notices;
    section.summary.push_back(std::move(entry));
  }
  return section;
}

}  // namespace rbcsim::report
