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

std::vector<svg::PlotPoint> deformation_over_time(const RunDirectory& run) {
  const auto table = run.csv(std::string(kTimeSeriesFile));
  const auto time_s = table.numbers("time_s");
  const auto deformation_index = table.numbers("deformation_index");
  std::vector<svg::PlotPoint> points;
  for (std::size_t i = 0; i < time_s.size(); ++i)
    points.push_back({time_s[i], deformation_index[i]});
  return points;
}

double transit_time_s(const RunDirectory& run) {
  return run.section().at("transit_time_s").number();
}

// A failed or interrupted run with a capillary object and its time series: drawn up to its stop.
bool has_deformation_trace(const RunDirectory& run) {
  if (run.succeeded()) return true;
  const auto section = run.result.find(run.command);
  return section != run.result.end() && section->contains("geometry") &&
         std::filesystem::exists(run.directory / kTimeSeriesFile);
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
  section.blocks.emplace_back(
      Paragraph{sentence + ". The paper finds discocyte < echinocyte III < stomatocyte II: " +
                (agrees ? "same order." : "different order.")});
  return {{"terms", terms},
          {"geometry", geometry},
          {"order", order},
          {"paper_order", paper_order},
          {"agrees_with_paper", agrees}};
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
  auto terms = membrane::all_force_term_names();
  std::erase_if(terms, [](const std::string& term) {
    return term == "area_difference" || term == "total_curvature";
  });
  return describe_terms(terms);
}

// The paper's Fig. 13: with F_ad and F_tc the cell's DI stays lower than without them. For each
// run with all six terms, against every run of the same cell through the same tube with the
// other four only: the two peak DIs.
nlohmann::json peak_deformation_by_terms(const RunList& runs, Section& section) {
  const std::string all_terms = describe_terms(membrane::all_force_term_names());
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
    if (!run.succeeded()) continue;
    runs.push_back(&run);
    labels.push_back(traced_labels[i]);
    colours.push_back(svg::palette_colour(i));
  }

  svg::BarChart transit{"Transit time through the narrow section", "transit time (s)", {}};
  std::vector<LabelledObject> rows;
  auto run_summaries = nlohmann::json::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    transit.bars.push_back({labels[i], transit_time_s(*runs[i]), colours[i]});
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
  const auto orders = transit_orders(runs, section);
  const auto peaks = peak_deformation_by_terms(runs, section);
  section.blocks.emplace_back(table_of_objects("Capillary results", "run", rows));
  section.blocks.emplace_back(headline_table(runs, labels));
  section.summary = {{"runs", run_summaries},
                     {"transit_time_order", orders},
                     {"peak_deformation_index_by_terms", peaks}};
  return section;
}

}  // namespace rbcsim::report
