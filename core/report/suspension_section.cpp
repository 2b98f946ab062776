// Suspensions in a straight periodic tube (`capillary --geometry tube --hematocrit H`;
// docs/physics.md, "Suspensions"): the whole flow over time (relative apparent viscosity, tube and
// discharge hematocrit, cell-free layer), the Fahraeus-Lindqvist and Fahraeus plots against the
// in-vitro fits of Pries et al., where the cells' centres sit across the tube, every run's
// averages against those fits and the cell-free-layer reference, and a mixture beside the
// discocytes-only run of the same tube and hematocrit. A run that stopped is drawn in the time
// plots up to its stop and left out of everything that needs its averages.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/track_change.hpp"

#include "report/markup.hpp"
#include "report/reference_data.hpp"
#include "report/sections.hpp"
#include "report/svg_plot.hpp"

namespace rbcsim::report {
// Named: a unity build joins the report's sections into one translation unit, where their
// anonymous namespaces merge.
namespace suspension_parts {
namespace {

constexpr std::string_view kTimeSeriesFile = "suspension_timeseries.csv";
constexpr std::string_view kCellsFile = "cells_timeseries.csv";
// Two runs are "the same tube and hematocrit" for the mixture comparison within these.
constexpr double kSameDiameter_um = 0.01;
constexpr double kSameHematocrit = 0.02;
// A cell-free-layer reference applies to a run of its tube diameter and hematocrit within these.
constexpr double kReferenceDiameter_um = 0.5;
constexpr double kReferenceHematocrit = 0.05;
constexpr int kRadialBins = 10;
// A suspension released from a packing becomes blood (the cells migrate to the axis and leave a
// cell-free layer of their own) only after the flow has carried it 25-50 tube diameters (Chien,
// Gompper & Fedosov, arXiv:2003.09217, from a dispersed start as ours): before the lower end a run
// measures its packing, not the flow Pries et al. measured.
constexpr double kDevelopedTravel_diameters = 25.0;

double number_of(const RunDirectory& run, std::string_view key) {
  return run.section().at(key).number();
}

// "32 discocyte + 8 echinocyte-III": the cells of each morphology that the run holds.
std::string mixture_of(const RunDirectory& run) {
  std::string mixture;
  for (const auto& [name, count] : run.section().at("cells_per_morphology").object().items()) {
    if (count.get<int>() == 0) continue;
    mixture += (mixture.empty() ? "" : " + ") + std::to_string(count.get<int>()) + " " + name;
  }
  return mixture;
}

bool discocytes_only(const RunDirectory& run) {
  for (const auto& [name, count] : run.section().at("cells_per_morphology").object().items()) {
    if (count.get<int>() > 0 && name != "discocyte") return false;
  }
  return true;
}

// "D 20 um, H_T 0.3: 40 discocyte", and the membrane terms when not all six.
std::string suspension_label(const RunDirectory& run) {
  std::string label = "D " + format_significant(number_of(run, "tube_diameter_um"), 3) +
                      " um, H_T " + format_significant(number_of(run, "packed_hematocrit"), 2) +
                      ": " + mixture_of(run);
  if (run.terms != "all six") label += ", " + run.terms;
  return label;
}

// A stopped run with its suspension object and time series: drawn up to its stop.
bool has_trace(const RunDirectory& run) {
  if (run.succeeded()) return true;
  const auto section = run.result.find(run.command);
  return section != run.result.end() && section->contains("tube_diameter_um") &&
         section->contains("cells_per_morphology") &&
         std::filesystem::exists(run.directory / kTimeSeriesFile);
}

// A finished run with samples in its averaging window: its averages are results.
bool has_averages(const RunDirectory& run) {
  return run.succeeded() && number_of(run, "averaging_samples") > 0;
}

// One column of the run's suspension_timeseries.csv (read once per run) against time.
std::vector<svg::PlotPoint> over_time(const io::CsvTable& table, std::string_view column) {
  const auto time_s = table.numbers("time_s");
  const auto values = table.numbers(column);
  std::vector<svg::PlotPoint> points;
  for (std::size_t i = 0; i < time_s.size(); ++i) points.push_back({time_s[i], values[i]});
  return points;
}

// Where the run's averages start: the last suspension.averaging_fraction of the run.
double averaging_start_s(const RunDirectory& run) {
  const double fraction = run.config_field().at("suspension").at("averaging_fraction").number();
  return number_of(run, "time_s") * (1.0 - fraction);
}

// The cells' centres over the averaging window, per radial bin of the tube: their share of the
// centres over the bin's share of the cross-section (1 = spread evenly over the lumen). One
// series per morphology of the run (its index in result.json's "morphologies").
std::vector<std::vector<svg::PlotPoint>> centre_densities(const RunDirectory& run) {
  const auto table = run.csv(std::string(kCellsFile));
  const auto time_s = table.numbers("time_s");
  const auto morphology = table.numbers("morphology_index");
  const auto radius_um = table.numbers("radial_position_um");
  const double tube_radius_um = number_of(run, "tube_diameter_um") / 2.0;
  const double from_s = averaging_start_s(run);
  const std::size_t morphologies = run.section().at("morphologies").array_size();
  std::vector<std::vector<double>> counts(morphologies, std::vector<double>(kRadialBins, 0.0));
  std::vector<double> totals(morphologies, 0.0);
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    if (time_s[i] < from_s || time_s[i] == 0.0) continue;
    const auto m = static_cast<std::size_t>(morphology[i]);
    if (m >= morphologies) continue;
    const int bin = std::clamp(static_cast<int>(radius_um[i] / tube_radius_um * kRadialBins), 0,
                               kRadialBins - 1);
    counts[m][static_cast<std::size_t>(bin)] += 1.0;
    totals[m] += 1.0;
  }
  std::vector<std::vector<svg::PlotPoint>> densities(morphologies);
  for (std::size_t m = 0; m < morphologies; ++m) {
    if (totals[m] == 0.0) continue;
    for (int bin = 0; bin < kRadialBins; ++bin) {
      const double inner = static_cast<double>(bin) / kRadialBins;
      const double outer = static_cast<double>(bin + 1) / kRadialBins;
      const double area_share = outer * outer - inner * inner;
      densities[m].push_back({(inner + outer) / 2.0,
                              counts[m][static_cast<std::size_t>(bin)] / totals[m] / area_share});
    }
  }
  return densities;
}

std::vector<svg::PlotPoint> curve(double low_um, double high_um,
                                  const std::function<double(double)>& value_at) {
  std::vector<svg::PlotPoint> points;
  constexpr int kIntervals = 80;
  for (int i = 0; i <= kIntervals; ++i) {
    const double diameter_um = low_um + (high_um - low_um) * i / kIntervals;
    points.push_back({diameter_um, value_at(diameter_um)});
  }
  return points;
}

// The reference's curves at H_D 0.30 and 0.45 over the runs' diameters and beyond, and the
// reference at each run's own diameter and measured H_D, for a plot of a quantity against D.
void add_reference(svg::LinePlot& plot, const RunList& runs, const std::string& name,
                   double (*reference)(double, double)) {
  double low_um = 5.0;
  double high_um = 50.0;
  for (const auto* run : runs) {
    low_um = std::min(low_um, 0.8 * number_of(*run, "tube_diameter_um"));
    high_um = std::max(high_um, 1.25 * number_of(*run, "tube_diameter_um"));
  }
  for (const double hematocrit : {0.45, 0.30}) {
    plot.series.push_back(
        {name + ", H_D " + format_significant(hematocrit, 2),
         curve(low_um, high_um, [&](double d) { return reference(d, hematocrit); }),
         std::string(svg::kReferenceColour), svg::Marker::none, true, hematocrit != 0.45});
  }
  std::vector<svg::PlotPoint> at_runs;
  for (const auto* run : runs) {
    const double diameter_um = number_of(*run, "tube_diameter_um");
    at_runs.push_back(
        {diameter_um, reference(diameter_um, number_of(*run, "discharge_hematocrit"))});
  }
  plot.series.push_back({name + " at each run's measured H_D", at_runs,
                         std::string(svg::kReferenceColour), svg::Marker::diamond, false});
}

struct Comparison {
  std::string what;
  std::string ours;
  std::string reference;
  std::string difference;
  std::string verdict;
};

nlohmann::json to_json(const Comparison& c) {
  return {{"comparison", c.what},
          {"rbcsim", c.ours},
          {"reference", c.reference},
          {"difference", c.difference},
          {"verdict", c.verdict}};
}

Comparison against_fit(const std::string& what, double ours, double fit,
                       const std::string& reference) {
  const double difference = ours / fit - 1.0;
  return {what, format_significant(ours), format_significant(fit) + " (" + reference + ")",
          format_significant(100.0 * difference, 3) + " %", pries_verdict(difference)};
}

// How many tube diameters the flow carried the cells: result.json's figure, or for a run written
// before it existed the same measure from its cells' centroids in cells_timeseries.csv; nullopt
// when neither says.
std::optional<double> travel_tube_diameters(const RunDirectory& run) {
  if (const auto recorded = run.section().find("cell_travel_tube_diameters")) {
    return recorded->number();
  }
  if (!std::filesystem::exists(run.directory / kCellsFile)) return std::nullopt;
  const auto table = run.csv(std::string(kCellsFile));
  for (const char* column : {"time_s", "cell_id", "centroid_x_um"}) {
    if (!table.has_column(column)) return std::nullopt;
  }
  const auto time_s = table.numbers("time_s");
  const auto cell = table.numbers("cell_id");
  const auto x_um = table.numbers("centroid_x_um");
  std::vector<TrackSample> samples;
  for (std::size_t row = 0; row < time_s.size(); ++row) {
    samples.push_back({static_cast<std::size_t>(cell[row]), time_s[row], x_um[row]});
  }
  return mean_change_per_track(samples) / number_of(run, "tube_diameter_um");
}

// Why a run's averages get no verdict, or "" when they do: cells that pierced each other, or a
// flow not yet developed (kDevelopedTravel_diameters).
std::string withheld_because(const RunDirectory& run) {
  const int pierced = run.section().at("samples_with_pierced_cells").integer();
  if (pierced > 0) {
    return "not a result: cells pierced each other in " + std::to_string(pierced) + " samples";
  }
  const auto travel = travel_tube_diameters(run);
  if (!travel) return "not a result: how far the flow carried the cells was not recorded";
  if (*travel < kDevelopedTravel_diameters) {
    return "not developed: the cells travelled " + format_significant(*travel, 2) +
           " tube diameters of the 25-50 a packing needs (Chien et al.)";
  }
  return "";
}

// Every run's averages against Pries et al. at its diameter and measured H_D, and its cell-free
// layer against the references of its tube and hematocrit.
std::vector<Comparison> comparisons_of(const RunDirectory& run, const std::string& label) {
  const double diameter_um = number_of(run, "tube_diameter_um");
  const double discharge = number_of(run, "discharge_hematocrit");
  const double tube = number_of(run, "tube_hematocrit");
  const std::string at = " at D " + format_significant(diameter_um, 3) + " um, H_D " +
                         format_significant(discharge, 3);
  std::vector<Comparison> comparisons{
      against_fit("suspension " + label + ": relative apparent viscosity",
                  number_of(run, "relative_apparent_viscosity"),
                  pries1992_relative_apparent_viscosity(diameter_um, discharge),
                  "Pries et al. 1992 in vitro" + at),
      against_fit("suspension " + label + ": H_T / H_D (Fahraeus)",
                  number_of(run, "tube_to_discharge_hematocrit"),
                  pries1990_tube_to_discharge_hematocrit(diameter_um, discharge),
                  "Pries et al. 1990" + at)};
  for (const auto& reference : cell_free_layer_reference()) {
    if (reference.hematocrit_kind != "tube" ||
        std::abs(reference.diameter_um - diameter_um) > kReferenceDiameter_um ||
        std::abs(reference.hematocrit - tube) > kReferenceHematocrit) {
      continue;
    }
    const double layer_um = number_of(run, "cell_free_layer_um");
    comparisons.push_back(
        {"suspension " + label + ": cell-free layer (um)", format_significant(layer_um),
         format_significant(reference.cell_free_layer_um) + " +- " +
             format_significant(reference.uncertainty_um, 2) + " at H_T " +
             format_significant(reference.hematocrit, 2) + " (" + reference.source + ", " +
             reference.status + ")",
         format_significant(layer_um - reference.cell_free_layer_um, 3) + " um",
         reference.status == "RECALLED" ? "scale only (a recalled value, not a bound)"
         : std::abs(layer_um - reference.cell_free_layer_um) <= reference.uncertainty_um
             ? "within the uncertainty"
             : "outside the uncertainty"});
  }
  // Cells that passed through each other are not a suspension, and a flow that has not carried
  // its cells far enough is not yet blood: the numbers are shown, the verdict withheld.
  const std::string withheld = withheld_because(run);
  if (!withheld.empty()) {
    for (auto& comparison : comparisons) comparison.verdict = withheld;
  }
  return comparisons;
}

// Each run with cells other than discocytes against a discocytes-only run of the same tube and
// packed hematocrit: the mixture's viscosity over the discocytes'.
nlohmann::json mixture_comparisons(const RunList& runs, const std::vector<std::string>& labels,
                                   Section& section) {
  auto mixtures = nlohmann::json::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (discocytes_only(*runs[i])) continue;
    for (std::size_t j = 0; j < runs.size(); ++j) {
      const auto& mixed = *runs[i];
      const auto& plain = *runs[j];
      if (!discocytes_only(plain) ||
          std::abs(number_of(plain, "tube_diameter_um") - number_of(mixed, "tube_diameter_um")) >
              kSameDiameter_um ||
          std::abs(number_of(plain, "packed_hematocrit") - number_of(mixed, "packed_hematocrit")) >
              kSameHematocrit) {
        continue;
      }
      const double ours = number_of(mixed, "relative_apparent_viscosity");
      const double theirs = number_of(plain, "relative_apparent_viscosity");
      const double spread = std::hypot(number_of(mixed, "relative_apparent_viscosity_sd"),
                                       number_of(plain, "relative_apparent_viscosity_sd"));
      const bool resolved = std::abs(ours - theirs) > 2.0 * spread;
      section.blocks.emplace_back(Paragraph{
          "Mixture: " + labels[i] + " has relative apparent viscosity " + format_significant(ours) +
          " against " + format_significant(theirs) + " for " + labels[j] + " (ratio " +
          format_significant(ours / theirs) + "; the difference " +
          format_significant(ours - theirs, 3) + (resolved ? " exceeds" : " is within") +
          " twice the combined standard deviation over the averaging window, " +
          format_significant(2.0 * spread, 3) + ")."});
      mixtures.push_back({{"mixture", labels[i]},
                          {"discocytes_only", labels[j]},
                          {"relative_apparent_viscosity", ours},
                          {"discocytes_only_relative_apparent_viscosity", theirs},
                          {"ratio", ours / theirs},
                          {"resolved_beyond_twice_the_spread", resolved}});
    }
  }
  return mixtures;
}

svg::LinePlot against_diameter(const RunList& runs, const std::vector<std::string>& labels,
                               const std::vector<std::string>& colours, const std::string& title,
                               const std::string& y_label, const std::string& key,
                               const std::string& spread_key) {
  svg::LinePlot plot{title, "tube diameter D (um)", y_label, {}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const double spread = spread_key.empty() ? 0.0 : number_of(*runs[i], spread_key);
    plot.series.push_back(
        {labels[i],
         {{number_of(*runs[i], "tube_diameter_um"), number_of(*runs[i], key), spread}},
         colours[i],
         svg::Marker::circle,
         false});
  }
  return plot;
}

std::string row_text(const RunDirectory& run, std::string_view key, int digits = 4) {
  return format_significant(number_of(run, key), digits);
}

Table results_table(const RunList& runs, const std::vector<std::string>& labels) {
  Table table{
      "Averages over each run's averaging window, against the in-vitro fits at the run's "
      "diameter and measured discharge hematocrit",
      {"run", "cells", "packed H_T", "H_T", "H_D", "H_T / H_D", "Pries 1990 H_T / H_D",
       "relative apparent viscosity", "Pries 1992", "rbcsim / Pries 1992", "cell-free layer (um)",
       "pseudo-shear rate (1/s)", "cells' travel (tube diameters)", "samples with pierced cells",
       "force-capped steps"},
      {}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& run = *runs[i];
    const double diameter_um = number_of(run, "tube_diameter_um");
    const double discharge = number_of(run, "discharge_hematocrit");
    const double pries = pries1992_relative_apparent_viscosity(diameter_um, discharge);
    const auto travel = travel_tube_diameters(run);
    table.rows.push_back(
        {labels[i], std::to_string(run.section().at("cells").integer()),
         row_text(run, "packed_hematocrit", 3), row_text(run, "tube_hematocrit", 3),
         row_text(run, "discharge_hematocrit", 3), row_text(run, "tube_to_discharge_hematocrit", 3),
         format_significant(pries1990_tube_to_discharge_hematocrit(diameter_um, discharge), 3),
         row_text(run, "relative_apparent_viscosity") + " +- " +
             row_text(run, "relative_apparent_viscosity_sd", 2),
         format_significant(pries),
         format_significant(number_of(run, "relative_apparent_viscosity") / pries, 3),
         row_text(run, "cell_free_layer_um", 3), row_text(run, "pseudo_shear_rate_per_s", 3),
         travel ? format_significant(*travel, 3) : "-",
         std::to_string(run.section().at("samples_with_pierced_cells").integer()),
         std::to_string(run.section().at("force_capped_steps").integer())});
  }
  return table;
}

void add_time_plots(const RunList& traced, const std::vector<std::string>& labels,
                    Section& section) {
  svg::LinePlot viscosity{"Relative apparent viscosity vs time",
                          "time (s)",
                          "relative apparent viscosity Q_plasma / Q",
                          {}};
  svg::LinePlot hematocrit{
      "Tube (solid) and discharge (dashed) hematocrit vs time", "time (s)", "hematocrit", {}};
  svg::LinePlot layer{"Cell-free layer vs time", "time (s)", "cell-free layer (um)", {}};
  for (std::size_t i = 0; i < traced.size(); ++i) {
    const auto& run = *traced[i];
    const auto label = label_with_status(run, labels[i]);
    const auto colour = svg::palette_colour(i);
    const bool stopped = !run.succeeded();
    const auto series = run.csv(std::string(kTimeSeriesFile));
    viscosity.series.push_back({label, over_time(series, "relative_apparent_viscosity"), colour,
                                svg::Marker::none, true, stopped});
    hematocrit.series.push_back({label + ": H_T", over_time(series, "tube_hematocrit"), colour,
                                 svg::Marker::none, true, false});
    hematocrit.series.push_back({label + ": H_D", over_time(series, "discharge_hematocrit"), colour,
                                 svg::Marker::none, true, true});
    layer.series.push_back(
        {label, over_time(series, "cell_free_layer_um"), colour, svg::Marker::none, true, stopped});
  }
  const std::string source = " (" + std::string(kTimeSeriesFile) + ").";
  section.blocks.emplace_back(
      Figure{svg::render_line_plot(viscosity),
             "The plasma's flow rate under the same pressure gradient over the suspension's: 1 is "
             "plasma alone. Each run's average is over its last suspension.averaging_fraction" +
                 source});
  section.blocks.emplace_back(Figure{
      svg::render_line_plot(hematocrit),
      "Tube hematocrit (cell volume over lumen) and discharge hematocrit (the cells' share of the "
      "flow rate); H_T < H_D is the Fahraeus effect" +
          source});
  section.blocks.emplace_back(
      Figure{svg::render_line_plot(layer),
             "Radius minus the mean outermost cell radius over axial and angular bins" + source});
}

// The radial distribution of the centres (centre_densities) of every run with a cells file, as
// one plot, and per run in the summary: {"ring_midpoints_r_over_R": [...], morphology: [...]}.
std::vector<nlohmann::json> add_radial_plot(const RunList& runs,
                                            const std::vector<std::string>& labels,
                                            const std::vector<std::string>& colours,
                                            Section& section) {
  svg::LinePlot plot{"Where the cells' centres are across the tube",
                     "radial position r / R",
                     "share of centres over share of area",
                     {}};
  const svg::Marker markers[] = {svg::Marker::circle, svg::Marker::square, svg::Marker::triangle,
                                 svg::Marker::diamond};
  std::vector<nlohmann::json> summaries(runs.size(), nullptr);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!std::filesystem::exists(runs[i]->directory / kCellsFile)) continue;
    const auto densities = centre_densities(*runs[i]);
    const auto& names = runs[i]->section().at("morphologies").json();
    for (std::size_t m = 0; m < densities.size(); ++m) {
      if (densities[m].empty()) continue;
      const std::string name = names.at(m).get<std::string>();
      plot.series.push_back({labels[i] + (densities.size() > 1 ? ": " + name : ""), densities[m],
                             colours[i], markers[m % std::size(markers)], true, m > 0});
      auto midpoints = nlohmann::json::array();
      auto values = nlohmann::json::array();
      for (const auto& point : densities[m]) {
        midpoints.push_back(point.x);
        values.push_back(point.y);
      }
      summaries[i]["ring_midpoints_r_over_R"] = midpoints;
      summaries[i][name] = values;
    }
  }
  if (plot.series.empty()) return summaries;
  section.blocks.emplace_back(Figure{
      svg::render_line_plot(plot),
      "Cell centres over each run's averaging window in " + std::to_string(kRadialBins) +
          " rings of equal width (" + std::string(kCellsFile) +
          "); 1 is an even spread over the cross-section. A centre cannot come closer to the "
          "wall than about a cell's half-thickness; aged cells pushed to the wall (margination) "
          "show as a peak near r / R = 1."});
  return summaries;
}

// The hematocrit profile (result.json "hematocrit_profile": the cells' volume fraction in rings
// about the axis, averaged over the run's window) of every run that has one, as one plot, and per
// run in the summary: {"r_over_R": ring midpoints, "volume_fraction": [...]} (null without one).
std::vector<nlohmann::json> add_profile_plot(const RunList& runs,
                                             const std::vector<std::string>& labels,
                                             const std::vector<std::string>& colours,
                                             Section& section) {
  std::vector<nlohmann::json> summaries(runs.size(), nullptr);
  svg::LinePlot plot{
      "Hematocrit across the tube", "radial position r / R", "volume fraction of cells", {}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto profile = runs[i]->section().find("hematocrit_profile");
    if (!profile) continue;
    const auto inner = profile->at("ring_inner_radius_um");
    const auto outer = profile->at("ring_outer_radius_um");
    const auto fraction = profile->at("volume_fraction");
    const double radius_um = 0.5 * runs[i]->section().at("tube_diameter_um").number();
    std::vector<svg::PlotPoint> points;
    for (std::size_t ring = 0; ring < fraction.array_size(); ++ring) {
      const double middle_um = 0.5 * (inner.at(ring).number() + outer.at(ring).number());
      points.push_back({middle_um / radius_um, fraction.at(ring).number()});
      summaries[i]["r_over_R"].push_back(points.back().x);
      summaries[i]["volume_fraction"].push_back(points.back().y);
    }
    plot.series.push_back({labels[i], points, colours[i], svg::Marker::circle, true, false});
  }
  if (plot.series.empty()) return summaries;
  section.blocks.emplace_back(
      Figure{svg::render_line_plot(plot),
             "The cells' volume fraction in rings of equal width about the axis, averaged over "
             "each run's window (hematocrit_profile.csv has every sample): the core the cells "
             "crowd into, and the cell-free layer as the fall to 0 at the wall."});
  return summaries;
}

}  // namespace
}  // namespace suspension_parts

Section build_suspension_section(const RunList& all_runs) {
  using namespace suspension_parts;
  Section section{"suspension", "Suspensions in a straight tube", {}, {}};
  const auto traced = plotted_runs(all_runs, section, has_trace);
  name_unfinished_runs(traced,
                       "Drawn dashed in the time plots up to where they stopped, and left out of "
                       "the averages and comparisons",
                       section);
  const auto traced_labels = distinct_labels(traced, suspension_label);
  add_time_plots(traced, traced_labels, section);

  RunList runs;  // those with averages; a run keeps its label and colour in every plot
  std::vector<std::string> labels;
  std::vector<std::string> colours;
  for (std::size_t i = 0; i < traced.size(); ++i) {
    if (!has_averages(*traced[i])) continue;
    runs.push_back(traced[i]);
    labels.push_back(traced_labels[i]);
    colours.push_back(svg::palette_colour(i));
  }
  auto comparisons = nlohmann::json::array();
  auto run_summaries = nlohmann::json::array();
  nlohmann::json mixtures = nlohmann::json::array();
  if (!runs.empty()) {
    auto viscosity = against_diameter(runs, labels, colours,
                                      "Fahraeus-Lindqvist: apparent viscosity vs tube diameter",
                                      "relative apparent viscosity", "relative_apparent_viscosity",
                                      "relative_apparent_viscosity_sd");
    add_reference(viscosity, runs, "Pries et al. 1992 in vitro",
                  pries1992_relative_apparent_viscosity);
    auto fahraeus =
        against_diameter(runs, labels, colours, "Fahraeus: H_T / H_D vs tube diameter",
                         "tube / discharge hematocrit", "tube_to_discharge_hematocrit", "");
    add_reference(fahraeus, runs, "Pries et al. 1990", pries1990_tube_to_discharge_hematocrit);
    section.blocks.emplace_back(Figure{
        svg::render_line_plot(viscosity),
        "Each run's average (error bar: its standard deviation over the averaging window) against "
        "the in-vitro fit of Pries, Neuhaus, Gaehtgens (1992) for glass tubes at pseudo-shear "
        "rates >= 50 1/s, at H_D 0.45, 0.30 and at each run's measured discharge hematocrit "
        "(share/reference/pries_tube_flow.csv: the fit's formula was read in implementations "
        "that cite the paper, not in the paper)."});
    section.blocks.emplace_back(Figure{
        svg::render_line_plot(fahraeus),
        "Each run's average against the fit attributed to Pries, Secomb, Gaehtgens, Gross (1990); "
        "other codes use constants up to 0.015 apart for D 10-100 um."});
    const auto profiles = add_profile_plot(runs, labels, colours, section);
    const auto centres = add_radial_plot(runs, labels, colours, section);
    section.blocks.emplace_back(results_table(runs, labels));
    mixtures = mixture_comparisons(runs, labels, section);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      auto summary = run_summary(*runs[i]);
      summary["label"] = labels[i];
      summary["centre_density"] = centres[i];
      summary["hematocrit_profile"] = profiles[i];
      run_summaries.push_back(std::move(summary));
      for (const auto& comparison : comparisons_of(*runs[i], labels[i])) {
        comparisons.push_back(to_json(comparison));
      }
    }
    section.blocks.emplace_back(headline_table(runs, labels));
  }
  section.summary = {{"runs", run_summaries}, {"comparisons", comparisons}, {"mixtures", mixtures}};
  return section;
}

}  // namespace rbcsim::report
