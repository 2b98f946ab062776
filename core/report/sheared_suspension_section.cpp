// Sheared suspensions (`shear --hematocrit H`; docs/physics.md, "Sheared suspensions"): cells
// packed between two walls sliding in opposite directions, a Couette viscometer. The relative
// viscosity (the wall stress over the plasma's) against the shear rate, beside the high-shear
// limit of blood in wide tubes (Pries et al. 1992) at each run's hematocrit; its course over the
// strain per rate, with the independent near-wall measure; a table of every rate. A rate that
// stopped (a membrane failure, say) is drawn dashed in the strain plot up to its stop and left
// out of the plot against the rate and of the comparisons: its average is not a result.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/format.hpp"
#include "report/markup.hpp"
#include "report/reference_data.hpp"
#include "report/sections.hpp"
#include "report/svg_plot.hpp"

namespace rbcsim::report {
// Named: a unity build joins the report's sections into one translation unit, where their
// anonymous namespaces merge.
namespace sheared_suspension_parts {
namespace {

constexpr std::string_view kRatesMember = "rates";
constexpr std::string_view kTimeSeriesFile = "suspension_timeseries.csv";

// A rate with an average over its window and no failure: a result.
bool rate_is_result(const nlohmann::json& rate) {
  return !rate.contains("failure") && rate.value("averaged_samples", 0) > 0 &&
         rate.contains("relative_viscosity");
}

// The rates of result.json's object, read leniently (a stopped run's may be partial).
std::vector<nlohmann::json> rates_of(const RunDirectory& run) {
  const auto section = run.result.find(run.command);
  if (section == run.result.end() || !section->contains(kRatesMember)) return {};
  const auto& rates = section->at(kRatesMember);
  return rates.is_array() ? std::vector<nlohmann::json>(rates.begin(), rates.end())
                          : std::vector<nlohmann::json>{};
}

// "H 0.3, discocyte, 12 cells, physiological": what tells one sheared suspension from another.
std::string sheared_label(const RunDirectory& run) {
  const auto rates = rates_of(run);
  std::string morphologies;
  const auto section = run.result.find(run.command);
  if (section != run.result.end() && section->contains("morphologies")) {
    for (const auto& name : section->at("morphologies")) {
      morphologies += (morphologies.empty() ? "" : " + ") + name.get<std::string>();
    }
  }
  std::string label = "H " +
                      format_significant(run.result.at("headline").value("hematocrit", 0.0), 2) +
                      ", " + morphologies;
  if (!rates.empty()) label += ", " + std::to_string(rates.front().value("cells", 0)) + " cells";
  if (run.preset != "paper" && run.preset != "-") label += ", " + run.preset;
  if (run.terms != "all six") label += ", " + run.terms;
  return label;
}

std::string rate_text(const nlohmann::json& rate) {
  return format_significant(rate.at("shear_rate_per_s").get<double>(), 4) + " 1/s";
}

svg::LinePlot viscosity_against_rate(const RunList& runs, const std::vector<std::string>& labels) {
  svg::LinePlot plot{"Sheared suspension: relative viscosity vs shear rate",
                     "shear rate (1/s)",
                     "relative viscosity (wall stress / plasma's)",
                     {}};
  double lowest_rate = 0.0;
  double highest_rate = 0.0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::vector<svg::PlotPoint> points;
    for (const auto& rate : rates_of(*runs[i])) {
      if (!rate_is_result(rate)) continue;
      const double shear_rate = rate.at("shear_rate_per_s").get<double>();
      points.push_back({shear_rate, rate.at("relative_viscosity").get<double>(),
                        rate.value("relative_viscosity_sd", 0.0)});
      lowest_rate = lowest_rate == 0.0 ? shear_rate : std::min(lowest_rate, shear_rate);
      highest_rate = std::max(highest_rate, shear_rate);
    }
    if (points.empty()) continue;
    plot.series.push_back({label_with_status(*runs[i], labels[i]), points, svg::palette_colour(i),
                           svg::Marker::circle, true, false});
  }
  // The reference as a level line across the rates, once per hematocrit of the runs.
  std::vector<double> hematocrits;
  for (const auto* run : runs) {
    for (const auto& rate : rates_of(*run)) {
      if (!rate_is_result(rate)) continue;
      const double h = rate.at("hematocrit").get<double>();
      if (std::none_of(hematocrits.begin(), hematocrits.end(),
                       [h](double known) { return std::abs(known - h) < 0.005; })) {
        hematocrits.push_back(h);
      }
    }
  }
  const double span = std::max(highest_rate - lowest_rate, 0.2 * highest_rate);
  for (std::size_t k = 0; k < hematocrits.size(); ++k) {
    const double level = pries1992_large_tube_relative_viscosity(hematocrits[k]);
    plot.series.push_back(
        {"Pries et al. 1992, wide-tube limit, H " + format_significant(hematocrits[k], 2),
         {{lowest_rate - 0.1 * span, level}, {highest_rate + 0.1 * span, level}},
         std::string(svg::kReferenceColour),
         svg::Marker::none,
         true,
         k > 0});
  }
  return plot;
}

svg::LinePlot viscosity_over_strain(const RunList& runs, const std::vector<std::string>& labels) {
  svg::LinePlot plot{"Relative viscosity vs strain, each rate (thin: the near-wall measure)",
                     "strain (rate x time)",
                     "relative viscosity",
                     {}};
  std::size_t colour = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto rates = rates_of(*runs[i]);
    for (std::size_t r = 0; r < rates.size(); ++r) {
      if (!rates[r].contains("directory")) continue;  // runs before it was recorded
      const auto file =
          runs[i]->directory / rates[r].at("directory").get<std::string>() / kTimeSeriesFile;
      if (!std::filesystem::exists(file)) continue;
      const auto table = io::read_csv_file(file);
      const auto strain = table.numbers("strain");
      const auto stresslet = table.numbers("relative_viscosity");
      const auto near_wall = table.numbers("near_wall_relative_viscosity");
      std::vector<svg::PlotPoint> points;
      std::vector<svg::PlotPoint> wall_points;
      for (std::size_t k = 1; k < strain.size(); ++k) {  // the first sample is plasma at rest
        points.push_back({strain[k], stresslet[k]});
        wall_points.push_back({strain[k], near_wall[k]});
      }
      const bool stopped = !rate_is_result(rates[r]);
      const std::string label =
          labels[i] + ", " + rate_text(rates[r]) + (stopped ? " (stopped)" : "");
      const auto hue = svg::palette_colour(colour++);
      plot.series.push_back({label, points, hue, svg::Marker::none, true, stopped});
      plot.series.push_back(
          {label + ": near the walls", wall_points, hue, svg::Marker::none, true, true});
    }
  }
  return plot;
}

std::string rate_status(const nlohmann::json& rate) {
  if (rate_is_result(rate)) return "ok";
  return rate.contains("failure")
             ? "failed at strain " + format_significant(rate.value("strain", 0.0), 3)
             : "no average";
}

Table rates_table(const RunList& runs, const std::vector<std::string>& labels) {
  Table table{
      "Every rate: the mean over its averaging window (+- its standard deviation) and the "
      "high-shear limit of blood in wide tubes at its hematocrit",
      {"run", "rate (1/s)", "simulated rate (1/s)", "cells", "H", "strain reached",
       "relative viscosity", "near the walls", "stresslet / near-wall - 1",
       "Pries 1992 wide-tube limit", "rbcsim / Pries", "samples with pierced cells", "status"},
      {}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    for (const auto& rate : rates_of(*runs[i])) {
      const double hematocrit = rate.value("hematocrit", 0.0);
      const double ours = rate.value("relative_viscosity", std::nan(""));
      const double near_wall = rate.value("near_wall_relative_viscosity", std::nan(""));
      const double pries = pries1992_large_tube_relative_viscosity(hematocrit);
      table.rows.push_back(
          {labels[i], format_significant(rate.value("shear_rate_per_s", 0.0)),
           format_significant(rate.value("simulated_shear_rate_per_s", 0.0)),
           std::to_string(rate.value("cells", 0)), format_significant(hematocrit, 3),
           format_significant(rate.value("strain", 0.0), 3),
           format_significant(ours) + " +- " +
               format_significant(rate.value("relative_viscosity_sd", 0.0), 2),
           format_significant(near_wall),
           format_significant(100.0 * (ours / near_wall - 1.0), 2) + " %",
           format_significant(pries), format_significant(ours / pries, 3),
           std::to_string(rate.value("samples_with_pierced_cells", 0)), rate_status(rate)});
    }
  }
  return table;
}

// Each finished rate against the wide-tube limit at its hematocrit; withheld where cells pierced
// each other.
nlohmann::json comparisons_of(const RunDirectory& run, const std::string& label) {
  auto comparisons = nlohmann::json::array();
  for (const auto& rate : rates_of(run)) {
    if (!rate_is_result(rate)) continue;
    const double hematocrit = rate.at("hematocrit").get<double>();
    const double ours = rate.at("relative_viscosity").get<double>();
    const double pries = pries1992_large_tube_relative_viscosity(hematocrit);
    const double difference = ours / pries - 1.0;
    const int pierced = rate.value("samples_with_pierced_cells", 0);
    comparisons.push_back({{"comparison", "sheared suspension " + label + ", " + rate_text(rate) +
                                              ": relative viscosity"},
                           {"rbcsim", format_significant(ours)},
                           {"reference", format_significant(pries) +
                                             " (Pries et al. 1992, wide-tube high-shear "
                                             "limit at H " +
                                             format_significant(hematocrit, 3) + ")"},
                           {"difference", format_significant(100.0 * difference, 3) + " %"},
                           {"verdict", pierced > 0 ? "not a result: cells pierced each other in " +
                                                         std::to_string(pierced) + " samples"
                                                   : pries_verdict(difference)}});
  }
  return comparisons;
}

}  // namespace
}  // namespace sheared_suspension_parts

Section build_sheared_suspension_section(const RunList& all_runs) {
  using namespace sheared_suspension_parts;
  Section section{"sheared_suspension", "Sheared suspensions between walls", {}, {}};
  const auto runs = plotted_runs(all_runs, section, [](const RunDirectory& run) {
    return has_result_entries(run, std::string(kRatesMember), [](const nlohmann::json& rate) {
      return rate.contains("shear_rate_per_s");
    });
  });
  name_unfinished_runs(runs,
                       "Stopped runs: their finished rates are plotted, a stopped rate only in "
                       "the strain plot, dashed, up to its stop",
                       section);
  const auto labels = distinct_labels(runs, sheared_label);
  auto comparisons = nlohmann::json::array();
  auto run_summaries = nlohmann::json::array();
  if (!runs.empty()) {
    const auto against_rate = viscosity_against_rate(runs, labels);
    if (!against_rate.series.empty()) {
      section.blocks.emplace_back(Figure{
          svg::render_line_plot(against_rate),
          "Each finished rate's mean over the last suspension.averaging_fraction of its strain "
          "(error bar: the standard deviation of the samples there), from the stress the cells "
          "put into the fluid (Batchelor 1970). The level lines are the high-shear limit of "
          "blood in wide tubes (Pries, Neuhaus, Gaehtgens 1992, D -> infinity) at each run's "
          "hematocrit: a bulk figure, while the gap here is about three cell diameters and the "
          "cells keep off the walls, so a sheared gap need not match it."});
    }
    section.blocks.emplace_back(Figure{
        svg::render_line_plot(viscosity_over_strain(runs, labels)),
        "The stresslet measure (solid) and the velocity gradient in the two fluid layers next to "
        "each wall (dashed, the same colour): the two agree where no cell force reaches those "
        "layers (rate_<i>/suspension_timeseries.csv)."});
    section.blocks.emplace_back(rates_table(runs, labels));
    for (std::size_t i = 0; i < runs.size(); ++i) {
      auto summary = run_summary(*runs[i]);
      summary["label"] = labels[i];
      run_summaries.push_back(std::move(summary));
      for (auto& comparison : comparisons_of(*runs[i], labels[i])) {
        comparisons.push_back(std::move(comparison));
      }
    }
  }
  section.summary = {{"runs", run_summaries}, {"comparisons", comparisons}};
  return section;
}

}  // namespace rbcsim::report
