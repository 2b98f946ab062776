// The report's first section: every comparison of rbcsim with the paper and the reference data
// in one table (what, rbcsim, reference, difference, verdict), before the figures.
//   calibrate  every modulus the paper's §2.3 states, against the run's patch tests: agrees when
//              within kModulusAgreement;
//   stretch    the Mills et al. (2004) points inside both error bars;
//   capillary  the transit order against the paper's (discocyte < echinocyte III < stomatocyte
//              II), and whether the DI returns to its inlet value after the throat (Fig. 13);
//   suspension the apparent viscosity and the Fahraeus ratio against the in-vitro fits of Pries
//              et al. (within 15 %), the cell-free layer against its references (the section's
//              comparisons);
//   sheared_suspension  each finished rate's relative viscosity against the wide-tube high-shear
//              limit of Pries et al. 1992 at its hematocrit (the section's comparisons).
// Shear has no digitised reference here (the paper's Figs. 9-11 are only plotted).
#include <cmath>

#include "report/markup.hpp"
#include "report/sections.hpp"

namespace rbcsim::report {
namespace {

// The report's bound for a calibrated modulus to count as the paper's (5 %).
constexpr double kModulusAgreement = 0.05;
// The DI after the throat counts as returned to its inlet value within this.
constexpr double kReturnedDeformation = 0.1;

void modulus_row(const std::string& what, double ours, double paper, Table& table) {
  const double difference = ours / paper - 1.0;
  table.rows.push_back({what, format_significant(ours), format_significant(paper) + " (paper §2.3)",
                        format_significant(100.0 * difference, 3) + " %",
                        std::abs(difference) <= kModulusAgreement ? "agrees" : "differs"});
}

bool measures_isolated_patch(const nlohmann::json& test) {
  for (const auto& [key, value] : test.items()) {
    if (key.starts_with("isolated_patch_")) return true;
  }
  return false;
}

void calibrate_rows(const RunDirectory& run, const std::string& label, Table& table) {
  const auto& calibrate = run.section().object();
  const auto paper = calibrate.find("paper");
  if (paper == calibrate.end()) return;
  for (const auto& [test, reference] : paper->items()) {
    const auto measured = calibrate.find(test);
    if (!reference.is_object() || measured == calibrate.end() || !measured->is_object()) continue;
    for (const auto& [quantity, value] : reference.items()) {
      // The paper's inputs (k in kBT, fit targets) are not comparisons.
      if (!value.is_number() || quantity.ends_with("_kBT") || quantity.starts_with("target")) {
        continue;
      }
      // The hexagonal test measures an isolated 7-node patch (the paper's set-up) and the same
      // patch tiled as a sheet (the cell's membrane): the paper's figures are the former's.
      const auto isolated = measured->find("isolated_patch_" + quantity);
      if (isolated != measured->end() && isolated->is_number()) {
        modulus_row("calibrate " + label + ": " + test +
                        ", isolated patch (the paper's set-up): " + key_title(quantity),
                    isolated->get<double>(), value.get<double>(), table);
      }
      const auto ours = measured->find(quantity);
      if (ours == measured->end() || !ours->is_number()) continue;
      const std::string what =
          measures_isolated_patch(*measured) ? ", tiled sheet (the cell's membrane)" : "";
      modulus_row("calibrate " + label + ": " + test + what + ": " + key_title(quantity),
                  ours->get<double>(), value.get<double>(), table);
    }
  }
}

void stretch_rows(const RunDirectory& run, const std::string& label, Table& table) {
  const auto& stretch = run.section().object();
  const auto comparison = stretch.find("comparison");
  if (comparison == stretch.end() || !comparison->is_object()) return;
  const auto count = comparison->value("point_count", 0);
  const auto inside = comparison->value("inside_error_bars", 0);
  table.rows.push_back(
      {"stretch " + label + ": points inside both error bars",
       std::to_string(inside) + " of " + std::to_string(count), "Mills et al. 2004 (Fig. 8)", "—",
       inside == count ? "inside" : "outside at " + std::to_string(count - inside)});
}

void capillary_rows(const RunDirectory& run, const std::string& label, Table& table) {
  const auto& capillary = run.section().object();
  if (!capillary.value("passed", false)) return;
  const double initial = capillary.at("initial_deformation_index").get<double>();
  const double final_index = capillary.at("final_deformation_index").get<double>();
  table.rows.push_back(
      {"capillary " + label + ": DI after the throat against at the inlet",
       format_significant(final_index, 3) + " (inlet " + format_significant(initial, 3) +
           ", peak " + format_significant(capillary.at("peak_deformation_index").get<double>(), 3) +
           ")",
       "returns to the inlet value (paper Fig. 13)", format_significant(final_index - initial, 2),
       std::abs(final_index - initial) <= kReturnedDeformation ? "returns" : "does not"});
}

}  // namespace

Section build_verdict_section(const RunList& runs, const std::vector<Section>& sections) {
  Section section{"verdict",
                  "Verdict: rbcsim against the paper and the reference data",
                  {},
                  nlohmann::json::array()};
  Table table{"Every comparison of these runs (details in the sections below)",
              {"comparison", "rbcsim", "reference", "difference", "verdict"},
              {}};
  const auto labels = distinct_labels(runs, morphology_and_terms);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& run = *runs[i];
    if (!run.succeeded()) continue;
    if (run.command == "calibrate") calibrate_rows(run, labels[i], table);
    if (run.command == "stretch") stretch_rows(run, labels[i], table);
    if (run.command == "capillary") capillary_rows(run, labels[i], table);
  }
  for (const auto& other : sections) {
    if (other.id == "suspension" || other.id == "sheared_suspension") {
      for (const auto& comparison : other.summary.at("comparisons")) {
        std::vector<std::string> row;
        for (const char* column : {"comparison", "rbcsim", "reference", "difference", "verdict"}) {
          row.push_back(comparison.at(column).get<std::string>());
        }
        table.rows.push_back(std::move(row));
      }
    }
    if (other.id != "capillary") continue;
    for (const auto& order : other.summary.value("transit_time_order", nlohmann::json::array())) {
      std::string ours;
      for (const auto& morphology : order.at("order")) {
        ours += (ours.empty() ? "" : " < ") + morphology.get<std::string>();
      }
      std::string verdict =
          order.at("agrees_with_paper").get<bool>() ? "same order" : "other order";
      if (order.contains("resolved_by_ensemble_spread") &&
          !order.at("resolved_by_ensemble_spread").get<bool>()) {
        verdict += ", not resolved beyond twice the spread";
      }
      table.rows.push_back({"capillary transit order, " + order.at("geometry").get<std::string>() +
                                ", " + order.at("terms").get<std::string>(),
                            ours, "discocyte < echinocyte-III < stomatocyte-II (paper §3.4)", "—",
                            verdict});
    }
  }
  for (const auto& row : table.rows) {
    section.summary.push_back({{"comparison", row[0]},
                               {"rbcsim", row[1]},
                               {"reference", row[2]},
                               {"difference", row[3]},
                               {"verdict", row[4]}});
  }
  if (table.rows.empty()) {
    section.blocks.emplace_back(
        Paragraph{"No run here compares with the paper's numbers or the "
                  "reference data."});
  } else {
    section.blocks.emplace_back(std::move(table));
  }
  section.blocks.emplace_back(Paragraph{
      "Shear has no digitised reference in rbcsim (the paper's Figs. 9-11 are only plotted): see "
      "its section for the lengths and deformation indices against the shear rate."});
  return section;
}

}  // namespace rbcsim::report
