// Patch-test calibration (paper §2.3): every measured modulus and fitted stiffness
// beside the paper's value where result.json gives one.
#include "report/markup.hpp"
#include "report/sections.hpp"

namespace rbcsim::report {
namespace {

constexpr std::string_view kPaperKey = "paper";

// The paper's value of `quantity` of `test`: calibrate.paper.<test>.<quantity> if the writer
// grouped the paper's values by test, else calibrate.paper.<quantity>; "—" if neither exists.
std::string paper_value(const nlohmann::json* paper, const std::string& test,
                        const std::string& quantity) {
  if (paper == nullptr || !paper->is_object()) return "—";
  if (const auto group = paper->find(test); group != paper->end() && group->is_object()) {
    if (const auto value = group->find(quantity); value != group->end()) return format_cell(*value);
  }
  const auto value = paper->find(quantity);
  return value == paper->end() || value->is_object() ? "—" : format_cell(*value);
}

// A group of quantities inside a test (the stretch fit's comparison with Mills), one row each,
// named "<group>: <quantity>"; the paper has no such values.
void add_group_rows(Table& table, const std::string& test, const std::string& group,
                    const nlohmann::json& values) {
  for (const auto& [quantity, value] : values.items()) {
    table.rows.push_back(
        {test, key_title(group) + ": " + key_title(quantity), format_cell(value), "—"});
  }
}

Table calibration_table(const RunDirectory& run, const std::string& label) {
  const auto& calibrate = run.section().object();
  const auto paper = calibrate.find(kPaperKey);
  const nlohmann::json* paper_values = paper == calibrate.end() ? nullptr : &*paper;
  Table table{"Calibration: " + label, {"patch test", "quantity", "rbcsim", "paper"}, {}};
  for (const auto& [test, values] : calibrate.items()) {
    if (test == kPaperKey) continue;
    if (!values.is_object()) {
      table.rows.push_back(
          {"", key_title(test), format_cell(values), paper_value(paper_values, "", test)});
      continue;
    }
    for (const auto& [quantity, value] : values.items()) {
      if (value.is_object()) {
        add_group_rows(table, test, quantity, value);
        continue;
      }
      table.rows.push_back({test, key_title(quantity), format_cell(value),
                            paper_value(paper_values, test, quantity)});
    }
  }
  return table;
}

}  // namespace

Section build_calibrate_section(const RunList& all_runs) {
  Section section{"calibrate", "Calibration (patch tests)", {}, nlohmann::json::array()};
  const auto runs = plotted_runs(all_runs, section);
  const auto labels = distinct_labels(runs, morphology_and_terms);
  section.blocks.emplace_back(Paragraph{
      "Hexagonal patch: E_s, mu, K and the 2D Poisson ratio (K - mu)/(K + mu) from the link "
      "and area stiffnesses; two-triangle patch: bending stiffness from the dihedral moment "
      "(M = D dtheta/dx), then the fitted k_ad and k_c (paper §2.3, Table 2)."});
  for (std::size_t i = 0; i < runs.size(); ++i) {
    section.blocks.emplace_back(calibration_table(*runs[i], labels[i]));
    section.summary.push_back(run_summary(*runs[i]));
  }
  section.blocks.emplace_back(headline_table(runs, labels));
  return section;
}

}  // namespace rbcsim::report
