#include <algorithm>
#include <map>

#include "report/sections.hpp"

namespace rbcsim::report {

std::span<const ExperimentSection> experiment_sections() {
  static constexpr ExperimentSection kSections[] = {
      {"calibrate", build_calibrate_section},
      {"stretch", build_stretch_section},
      {"shear", build_shear_section},
      {"capillary", build_capillary_section},
      {"suspension", build_suspension_section},
      {"sheared_suspension", build_sheared_suspension_section},
  };
  return kSections;
}

std::vector<std::string> distinct_labels(
    const RunList& runs, const std::function<std::string(const RunDirectory&)>& describe) {
  std::vector<std::string> labels;
  std::map<std::string, int> uses;
  for (const auto* run : runs) ++uses[labels.emplace_back(describe(*run))];
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (uses[labels[i]] > 1) labels[i] += " (" + runs[i]->directory.generic_string() + ")";
  }
  return labels;
}

std::vector<std::string> distinct(const RunList& runs,
                                  const std::function<std::string(const RunDirectory&)>& value_of) {
  std::vector<std::string> values;
  for (const auto* run : runs) {
    auto value = value_of(*run);
    if (std::find(values.begin(), values.end(), value) == values.end()) {
      values.push_back(std::move(value));
    }
  }
  return values;
}

std::string morphology_and_terms(const RunDirectory& run) {
  return run.morphology + ", " + run.terms;
}

nlohmann::json run_identity(const RunDirectory& run) {
  return {{"directory", run.directory.generic_string()},
          {"morphology", run.morphology},
          {"preset", run.preset},
          {"terms", run.terms},
          {"forces", run.forces}};
}

nlohmann::json run_summary(const RunDirectory& run) {
  auto summary = run_identity(run);
  summary[run.command] = run.section().json();
  return summary;
}

RunList plotted_runs(const RunList& runs, Section& section,
                     const std::function<bool(const RunDirectory&)>& plotted) {
  RunList kept;
  std::string left_out;
  for (const auto* run : runs) {
    if (plotted(*run)) {
      kept.push_back(run);
    } else {
      left_out += (left_out.empty() ? "" : ", ") + run->directory.generic_string();
    }
  }
  if (!left_out.empty()) {
    section.blocks.emplace_back(Paragraph{
        "Failed or interrupted runs (listed under Runs, not plotted): " + left_out + "."});
  }
  return kept;
}

std::string label_with_status(const RunDirectory& run, const std::string& label) {
  return run.succeeded() ? label : label + " (" + run.status + ")";
}

bool has_result_entries(const RunDirectory& run, const std::string& member,
                        const std::function<bool(const nlohmann::json&)>& is_result) {
  if (run.succeeded()) return true;
  const auto section = run.result.find(run.command);
  if (section == run.result.end() || !section->is_object() || !section->contains(member)) {
    return false;
  }
  const auto& entries = section->at(member);
  return entries.is_array() && std::any_of(entries.begin(), entries.end(), [&](const auto& entry) {
           return entry.is_object() && is_result(entry);
         });
}

void name_unfinished_runs(const RunList& runs, const std::string& how_drawn, Section& section) {
  std::string unfinished;
  for (const auto* run : runs) {
    if (run->succeeded()) continue;
    unfinished += (unfinished.empty() ? "" : ", ") + run->directory.generic_string();
  }
  if (!unfinished.empty())
    section.blocks.emplace_back(Paragraph{how_drawn + ": " + unfinished + "."});
}

Table headline_table(const RunList& runs, const std::vector<std::string>& labels) {
  std::vector<LabelledObject> rows;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    rows.push_back({labels[i], runs[i]->result.at("headline")});
  }
  return table_of_objects("Headline numbers", "run", rows);
}

Section build_other_section(const std::string& command, std::size_t index, const RunList& runs) {
  Section section{"other-" + std::to_string(index), "Other runs: " + command, {}, {}};
  const auto labels = distinct_labels(runs, morphology_and_terms);
  section.blocks.emplace_back(headline_table(runs, labels));
  section.summary = {{"command", command}, {"runs", nlohmann::json::array()}};
  for (const auto* run : runs) {
    auto entry = run_identity(*run);
    entry["headline"] = run->result.at("headline");
    section.summary["runs"].push_back(std::move(entry));
  }
  return section;
}

}  // namespace rbcsim::report
