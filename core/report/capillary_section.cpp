// One cell through a stenosed capillary (paper §3.3-3.4): deformation index against
// time for every morphology (paper Fig. 13), transit times as bars, whether their order is the
// paper's, and whether F_ad and F_tc lower the peak DI as in the paper's Fig. 13. A run that
// failed or was interrupted is drawn in the DI plot up to where it stopped (where and how a cell
// fails is what a user wants to see), and left out of everything that needs a transit.
#include <algorithm>
#include <array>

#include "membrane/parameters.hpp"
#include "report/markup.hpp"
#include "report/sections.hpp"
#include "report/svg_plot.hpp"

namespace rbcsim::report {
namespace {

constexpr std::string_view kTimeSeriesFile = "capillary_timeseries.csv";

// The paper's conclusion: "The Discocyte RBC took less time, and the Stomatocyte II took more
// time to travel through the narrow segment" (Fig. 17 and §4), echinocyte III in between.
constexpr std::array<std::string_view, 3> kPaperTransitOrder{"discocyte", "echinocyte-III",
                                                             "stomatocyte-II"};

// The time series of the run: capillary_timeseries.csv, or the file result.json names (an
// ensemble's first release, orientation_0/capillary_timeseries.csv).
std::string timeseries_file(const RunDirectory& run) {
  const auto files = run.result.find("files");
  if (files != run.result.end() && files->contains("timeseries") &&
      (*files)["timeseries"].is_string()) {
    return (*files)["timeseries"].get<std::string>();
  }
  return std::string(kTimeSeriesFile);
}

// An ensemble of releases (--orientations): its result.json object, or nullptr.
const nlohmann::json* ensemble_of(const RunDirectory& run) {
  const auto ensemble = run.result.find("capillary_ensemble");
  return ensemble == run.result.end() ? nullptr : &*ensemble;
}

// Mean and standard deviation of an ensemble observable.
std::pair<double, double> ensemble_spread(const nlohmann::json& ensemble, const char* key) {
  const auto& statistics = ensemble.at("statistics").at(key);
  return {statistics.at("mean").get<double>(), statistics.at("standard_deviation").get<double>()};
}

std::vector<svg::PlotPoint> deformation_over_time(const RunDirectory& run) {
  const auto table = run.csv(timeseries_file(run));
  const auto time_s = table.numbers("time_s");
  const auto deformation_index = table.numbers("deformation_index");
  std::vector<svg::PlotPoint> points;
  for (std::size_t i = 0; i < time_s.size(); ++i)
    points.push_back({time_s[i], deformation_index[i]});
  return points;
}

// An ensemble some of whose releases passed: its statistics stand for the run even when another
// release failed (the run's status), which the ensemble table says.
bool has_passed_releases(const RunDirectory& run) {
  const auto* ensemble = ensemble_of(run);
  return ensemble && ensemble->at("passed").get<int>() > 0;
}

// The centroid's transit: an ensemble's mean, else the run's.
double transit_time_s(const RunDirectory& run) {
  if (const auto* ensemble = ensemble_of(run))
    return ensemble_spread(*ensemble, "transit_time_s").first;
  return run.section().at("transit_time_s").number();
}

// An ensemble's standard deviation of the transit; 0 for a single release.
double transit_spread_s(const RunDirectory& run) {
  if (const auto* ensemble = ensemble_of(run)) {
    return ensemble_spread(*ensemble, "transit_time_s").second;
  }
  return 0.0;
}

// A failed or interrupted run with a capillary object and its time series: drawn up to its stop.
bool has_deformation_trace(const RunDirectory& run) {
  if (run.succeeded()) return true;
  const auto section = run.result.find(run.command);
  return section != run.result.end() && section->contains("geometry") &&
         std::filesystem::exists(run.directory / timeseries_file(run));
}

// The tube the run went through: a built-in geometry's name or the wall file's.
std::string geometry_of(const RunDirectory& run) { return run.section().at("geometry").string(); }

bool is_in_paper_order(const std::string& morphology) {
  return std::find(kPaperTransitOrder.begin(), kPaperTransitOrder.end(), morphology) !=
         kPaperTransitOrder.end();
}

// The morphologies of `runs` (one run each, the same terms and tube) by increasing transit
// time, against the paper.
nlohmann::json transit_order(RunList runs, Section& section) {
  const std::string terms = runs.front()->terms;
  const std::string geometry = geometry_of(*runs.front());
  std::stable_sort(runs.begin(), runs.end(), [](const RunDirectory* a, const RunDirectory* b) {
    return transit_time_s(*a) < transit_time_s(*b);
  });
  std::vector<std::string> order;
  std::vector<std::string> known_order;
  std::string sentence = "Transit time order, " + terms + ", " + geometry + ": ";
  for (const auto* run : runs) {
    order.push_back(run->morphology);
    if (is_in_paper_order(run->morphology)) known_order.push_back(run->morphology);
    sentence += (order.size() > 1 ? " < " : "") + run->morphology + " (" +
                format_significant(transit_time_s(*run)) + " s)";
  }
  std::vector<std::string> paper_order;
  for (const auto morphology : kPaperTransitOrder) {
    const auto present = std::find(known_order.begin(), known_order.end(), morphology);
    if (present != known_order.end()) paper_order.emplace_back(morphology);
  }
  const bool agrees = known_order == paper_order;
  // With ensembles, a step of the order is a finding only when the gap exceeds twice the larger
  // of the two spreads over orientations.
  std::string robustness;
  bool robust = true;
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const double gap = transit_time_s(*runs[i]) - transit_time_s(*runs[i - 1]);
    const double spread = std::max(transit_spread_s(*runs[i]), transit_spread_s(*runs[i - 1]));
    if (spread == 0.0) continue;
    const bool clear = gap > 2.0 * spread;
    robust = robust && clear;
    robustness += " " + runs[i - 1]->morphology + " < " + runs[i]->morphology + ": gap " +
                  format_significant(gap, 3) + " s against twice the spread " +
                  format_significant(2.0 * spread, 3) + " s (" +
                  (clear ? "a finding" : "not resolved") + ").";
  }
  section.blocks.emplace_back(
      Paragraph{sentence + ". The paper finds discocyte < echinocyte III < stomatocyte II: " +
                (agrees ? "same order." : "different order.") + robustness});
  return {{"terms", terms},
          {"geometry", geometry},
          {"order", order},
          {"paper_order", paper_order},
          {"agrees_with_paper", agrees},
          {"resolved_by_ensemble_spread", robust}};
}

// Per set of membrane terms and tube in which every morphology ran once and at least two ran: the
// order (transit times through different tubes are not compared).
nlohmann::json transit_orders(const RunList& runs, Section& section) {
  auto orders = nlohmann::json::array();
  for (const auto& geometry : distinct(runs, geometry_of)) {
    for (const auto& terms : distinct(runs, &RunDirectory::terms)) {
      RunList group;
      std::vector<std::string> morphologies;
      for (const auto* run : runs) {
        if (run->terms != terms || geometry_of(*run) != geometry) continue;
        group.push_back(run);
        morphologies.push_back(run->morphology);
      }
      std::sort(morphologies.begin(), morphologies.end());
      const bool one_run_each =
          std::adjacent_find(morphologies.begin(), morphologies.end()) == morphologies.end();
      if (group.size() >= 2 && one_run_each) orders.push_back(transit_order(group, section));
    }
  }
  return orders;
}

double peak_deformation_index(const RunDirectory& run) {
  return run.section().at("peak_deformation_index").number();
}

// The paper's four-term model: every term but area difference and total curvature.
std::string four_terms() {
  auto terms = membrane::paper_force_term_names();
  std::erase_if(terms, [](const std::string& term) {
    return term == "area_difference" || term == "total_curvature";
  });
  return describe_terms(terms);
}

// The paper's Fig. 13: with F_ad and F_tc the cell's DI stays lower than without them. For each
// run with all six terms, against every run of the same cell through the same tube with the
// other four only: the two peak DIs.
nlohmann::json peak_deformation_by_terms(const RunList& runs, Section& section) {
  const std::string all_terms = describe_terms(membrane::paper_force_term_names());
  const std::string without_new_terms = four_terms();
  auto comparisons = nlohmann::json::array();
  for (const auto* with : runs) {
    if (with->terms != all_terms) continue;
    for (const auto* without : runs) {
      if (without->terms != without_new_terms || without->morphology != with->morphology ||
          geometry_of(*without) != geometry_of(*with)) {
        continue;
      }
      const double peak_with = peak_deformation_index(*with);
      const double peak_without = peak_deformation_index(*without);
      const bool lower = peak_with < peak_without;
      section.blocks.emplace_back(
          Paragraph{"Peak DI, " + with->morphology + ", " + geometry_of(*with) + ": " +
                    format_significant(peak_with) + " with all six terms, " +
                    format_significant(peak_without) + " " + without->terms + " (" +
                    (lower ? "lower" : "not lower") +
                    " with F_ad and F_tc; the paper's Fig. 13 has it lower with them)."});
      comparisons.push_back({{"morphology", with->morphology},
                             {"geometry", geometry_of(*with)},
                             {"terms", without->terms},
                             {"peak_deformation_index", peak_without},
                             {"all_six_peak_deformation_index", peak_with},
                             {"lower_with_all_six", lower}});
    }
  }
  return comparisons;
}

// "morphology, terms", and the tube when the runs went through more than one.
std::vector<std::string> capillary_labels(const RunList& runs) {
  if (distinct(runs, geometry_of).size() <= 1) return distinct_labels(runs, morphology_and_terms);
  return distinct_labels(runs, [](const RunDirectory& run) {
    return morphology_and_terms(run) + ", " + geometry_of(run);
  });
}

// The ensembles among `runs`: per run, the mean and spread of each transit and of the peak DI
// over its releases, and the confinement.
nlohmann::json ensemble_table(const RunList& runs, const std::vector<std::string>& labels,
                              Section& section) {
  auto summaries = nlohmann::json::array();
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto* ensemble = ensemble_of(*runs[i]);
    if (!ensemble) continue;
    auto spread_text = [&](const char* key) {
      const auto [mean, deviation] = ensemble_spread(*ensemble, key);
      return format_significant(mean) + " +- " + format_significant(deviation, 2);
    };
    const double confinement = runs[i]->section().at("confinement").number();
    rows.push_back({labels[i],
                    std::to_string(ensemble->at("passed").get<int>()) + " / " +
                        std::to_string(ensemble->at("orientations").get<int>()),
                    spread_text("transit_time_s"), spread_text("whole_cell_transit_time_s"),
                    spread_text("peak_deformation_index"), format_significant(confinement)});
    summaries.push_back(
        {{"run", labels[i]}, {"ensemble", *ensemble}, {"confinement", confinement}});
  }
  if (!rows.empty()) {
    section.blocks.emplace_back(
        Table{"Release orientations (mean +- standard deviation over the "
              "releases that passed)",
              {"run", "passed", "transit (s)", "whole-cell transit (s)", "peak DI", "confinement"},
              rows});
  }
  return summaries;
}

}  // namespace

Section build_capillary_section(const RunList& all_runs) {
  Section section{"capillary", "Capillary transit", {}, {}};
  const auto traced = plotted_runs(all_runs, section, has_deformation_trace);
  name_unfinished_runs(traced,
                       "Drawn dashed in the DI plot up to where they stopped, and left out of the "
                       "transit times and tables (no transit)",
                       section);
  const auto traced_labels = capillary_labels(traced);
  svg::LinePlot deformation{"Deformation index vs time", "time (s)", "deformation index DI", {}};
  RunList runs;  // those that finished; a run keeps its label and colour in both plots
  std::vector<std::string> labels;
  std::vector<std::string> colours;
  for (std::size_t i = 0; i < traced.size(); ++i) {
    const auto& run = *traced[i];
    deformation.series.push_back({label_with_status(run, traced_labels[i]),
                                  deformation_over_time(run), svg::palette_colour(i),
                                  svg::Marker::none, true, !run.succeeded()});
    if (!run.succeeded() && !has_passed_releases(run)) continue;
    runs.push_back(&run);
    labels.push_back(traced_labels[i]);
    colours.push_back(svg::palette_colour(i));
  }

  svg::BarChart transit{"Transit time through the narrow section", "transit time (s)", {}};
  std::vector<LabelledObject> rows;
  auto run_summaries = nlohmann::json::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    transit.bars.push_back(
        {labels[i], transit_time_s(*runs[i]), colours[i], transit_spread_s(*runs[i])});
    const auto capillary = runs[i]->section();
    rows.push_back({labels[i], capillary.object()});
    run_summaries.push_back(run_summary(*runs[i]));
  }
  section.blocks.emplace_back(
      Figure{svg::render_line_plot(deformation),
             "DI = (length in x) / (length in y) of the cell (paper Eq. 19) from " +
                 std::string(kTimeSeriesFile) + "; it peaks in the throat (paper Fig. 13)."});
  if (!runs.empty()) {
    section.blocks.emplace_back(Figure{svg::render_bar_chart(transit),
                                       "Time to cross the narrow section of the capillary."});
  }
  const auto ensembles = ensemble_table(runs, labels, section);
  const auto orders = transit_orders(runs, section);
  const auto peaks = peak_deformation_by_terms(runs, section);
  section.blocks.emplace_back(table_of_objects("Capillary results", "run", rows));
  section.blocks.emplace_back(headline_table(runs, labels));
  section.summary = {{"runs", run_summaries},
                     {"ensembles", ensembles},
                     {"transit_time_order", orders},
                     {"peak_deformation_index_by_terms", peaks}};
  return section;
}

}  // namespace rbcsim::report
