// One cell in simple shear (paper §3.2): cell length against shear rate per morphology,
// with and without the area-difference and total-curvature terms (the paper's Figs. 9-11), then
// the deformation index, surface smoothness and roughness of every run, and each sweep as a table.
#include <algorithm>

#include "report/markup.hpp"
#include "report/sections.hpp"
#include "report/svg_plot.hpp"

namespace rbcsim::report {
namespace {

constexpr std::string_view kRateKey = "shear_rate_per_s";

// A rate that failed (or was interrupted) has a "failure": its shape is the one it broke in.
bool rate_finished(const JsonField& rate) { return !rate.find("failure"); }

// A sweep is plotted when it finished, or when it failed or was interrupted after some of its
// rates finished: those rates are results (a cell that buckles at the highest rate is one of
// the paper's findings, not a reason to drop the rates below it).
bool has_finished_rates(const RunDirectory& run) {
  return has_result_entries(run, "rates",
                            [](const nlohmann::json& rate) { return !rate.contains("failure"); });
}

// (shear rate, rates[i][y_key]) of every finished rate that has a number there. A missing
// `required` key is bad input, naming the JSON path.
std::vector<svg::PlotPoint> sweep_points(const RunDirectory& run, std::string_view y_key,
                                         bool required) {
  const auto rates = run.section().at("rates");
  std::vector<svg::PlotPoint> points;
  for (std::size_t i = 0; i < rates.array_size(); ++i) {
    const auto rate = rates.at(i);
    if (!rate_finished(rate)) continue;
    const double x = rate.at(kRateKey).number();
    if (required) {
      points.push_back({x, rate.at(y_key).number()});
    } else if (const auto y = rate.find(y_key); y && y->json().is_number()) {
      points.push_back({x, y->number()});
    }
  }
  return points;
}

// Index of `value` in `values`, which holds it.
std::size_t index_in(const std::vector<std::string>& values, const std::string& value) {
  return static_cast<std::size_t>(std::find(values.begin(), values.end(), value) - values.begin());
}

// Every plot of the section draws a set of membrane terms with the same marker and line style
// (the first set solid, the others dashed); `colour_index` picks the colour.
svg::Series sweep_series(std::string label, std::vector<svg::PlotPoint> points,
                         std::size_t colour_index, std::size_t terms_index) {
  constexpr svg::Marker kMarkers[] = {svg::Marker::circle, svg::Marker::square,
                                      svg::Marker::triangle, svg::Marker::diamond};
  return {std::move(label),
          std::move(points),
          svg::palette_colour(colour_index),
          kMarkers[terms_index % std::size(kMarkers)],
          true,
          terms_index > 0};
}

struct SectionStyles {
  std::vector<std::string> term_sets;
  std::vector<std::string> morphologies;
};

// One morphology, coloured by term set: with and without the new terms side by side.
Figure length_figure(const std::string& morphology, const RunList& runs,
                     const SectionStyles& styles) {
  const auto labels = distinct_labels(runs, [](const RunDirectory& run) { return run.terms; });
  svg::LinePlot plot{
      "Cell length vs shear rate: " + morphology, "shear rate (1/s)", "cell length (µm)", {}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto terms = index_in(styles.term_sets, runs[i]->terms);
    plot.series.push_back(
        sweep_series(labels[i], sweep_points(*runs[i], "length_um", true), terms, terms));
  }
  return {svg::render_line_plot(plot),
          "Cell length (largest vertex-to-vertex distance) at steady state, " + morphology +
              ", one line per set of membrane terms (paper Figs. 9-11)."};
}

// All runs in one plot of `y_key`, coloured by morphology; nullopt when no run reports it.
std::optional<Figure> sweep_figure(const RunList& runs, const std::vector<std::string>& labels,
                                   const SectionStyles& styles, std::string_view y_key,
                                   const std::string& y_label, const std::string& title,
                                   const std::string& caption) {
  svg::LinePlot plot{title, "shear rate (1/s)", y_label, {}};
  bool any_points = false;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    auto points = sweep_points(*runs[i], y_key, false);
    any_points = any_points || !points.empty();
    plot.series.push_back(sweep_series(labels[i], std::move(points),
                                       index_in(styles.morphologies, runs[i]->morphology),
                                       index_in(styles.term_sets, runs[i]->terms)));
  }
  if (!any_points) return std::nullopt;
  return Figure{svg::render_line_plot(plot), caption};
}

// The plots of one observable against the shear rate, all runs in each.
struct SweepPlot {
  std::string_view y_key;
  const char* y_label;
  const char* title;
  const char* caption;
};
constexpr SweepPlot kSweepPlots[] = {
    {"deformation_index", "deformation index", "Deformation index vs shear rate",
     "Taylor deformation index (L - B)/(L + B) at steady state."},
    {"smoothness_rad", "smoothness (rad)", "Surface smoothness vs shear rate",
     "RMS change of the dihedral angles from the stress-free shape: the overall bending of the "
     "cell and any mesh-scale wrinkles together."},
    {"roughness_rad", "roughness (rad)", "Surface roughness vs shear rate",
     "Mesh-scale part of the dihedral change (its vertex mean minus the one-ring mean): near 0 "
     "for a smooth deformation, raised by wrinkles, creases and kinks, the paper's \"unnatural "
     "deformations\" without F_ad and F_tc."},
};

Table sweep_table(const RunDirectory& run, const std::string& label) {
  const auto rates = run.section().at("rates");
  std::vector<LabelledObject> rows;
  for (std::size_t i = 0; i < rates.array_size(); ++i) {
    const auto rate = rates.at(i);
    auto values = rate.object();
    values.erase(std::string(kRateKey));
    rows.push_back({format_cell(rate.at(kRateKey).json()), std::move(values)});
  }
  return table_of_objects("Shear sweep: " + label, key_title(kRateKey), rows);
}

// "stomatocyte-II, without ...: 2000 1/s; ..." for the rates that did not finish; empty if none.
std::string unfinished_rates(const RunList& runs, const std::vector<std::string>& labels) {
  std::string listed;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto rates = runs[i]->section().at("rates");
    std::string of_run;
    for (std::size_t r = 0; r < rates.array_size(); ++r) {
      if (rate_finished(rates.at(r))) continue;
      of_run +=
          (of_run.empty() ? "" : ", ") + format_cell(rates.at(r).at(kRateKey).json()) + " 1/s";
    }
    if (!of_run.empty()) listed += (listed.empty() ? "" : "; ") + labels[i] + ": " + of_run;
  }
  return listed;
}

}  // namespace

Section build_shear_section(const RunList& all_runs) {
  Section section{"shear", "Simple shear", {}, nlohmann::json::array()};
  const auto runs = plotted_runs(all_runs, section, has_finished_rates);
  const auto labels = distinct_labels(runs, morphology_and_terms);

  const SectionStyles styles{distinct(runs, &RunDirectory::terms),
                             distinct(runs, &RunDirectory::morphology)};
  for (const auto& morphology : styles.morphologies) {
    RunList of_morphology;
    std::copy_if(runs.begin(), runs.end(), std::back_inserter(of_morphology),
                 [&morphology](const RunDirectory* run) { return run->morphology == morphology; });
    section.blocks.emplace_back(length_figure(morphology, of_morphology, styles));
  }
  for (const auto& plot : kSweepPlots) {
    if (auto figure = sweep_figure(runs, labels, styles, plot.y_key, plot.y_label, plot.title,
                                   plot.caption)) {
      section.blocks.emplace_back(std::move(*figure));
    }
  }
  if (const auto unfinished = unfinished_rates(runs, labels); !unfinished.empty()) {
    section.blocks.emplace_back(Paragraph{
        "Rates that failed or were interrupted are in the tables below with their failure, not "
        "in the plots: " +
        unfinished + "."});
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    section.blocks.emplace_back(sweep_table(*runs[i], labels[i]));
    section.summary.push_back(run_summary(*runs[i]));
  }
  section.blocks.emplace_back(headline_table(runs, labels));
  return section;
}

}  // namespace rbcsim::report
