// Optical-tweezers stretching (paper §3.1, Fig. 8): axial and transverse diameters against
// force for every run, over the Mills et al. (2004) measurements with their error bars. A curve
// that stopped (a fluid stretch failing at its ninth force, say) is drawn up to its last force
// that reached its steady shape, and left out of the comparison: it is not the whole curve.
#include <algorithm>
#include <optional>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/config.hpp"
#include "report/reference_data.hpp"
#include "report/sections.hpp"
#include "report/svg_plot.hpp"

namespace rbcsim::report {
namespace {

struct Diameters {
  std::vector<svg::PlotPoint> axial;
  std::vector<svg::PlotPoint> transverse;
};

// A point a run did not bring to its steady shape has "converged": false (a finished run has
// none; a stopped one ends with the force it failed at).
bool converged(const JsonField& point) {
  const auto flag = point.find("converged");
  return !flag || flag->boolean();
}

// A stopped run with at least one converged point: drawn up to it.
bool has_converged_points(const RunDirectory& run) {
  return has_result_entries(run, "points", [](const nlohmann::json& point) {
    return point.contains("converged") && point.at("converged") == true;
  });
}

Diameters run_diameters(const RunDirectory& run) {
  const auto points = run.section().at("points");
  Diameters diameters;
  for (std::size_t i = 0; i < points.array_size(); ++i) {
    const auto point = points.at(i);
    if (!converged(point)) continue;
    const double force_pN = point.at("force_pN").number();
    diameters.axial.push_back({force_pN, point.at("axial_um").number()});
    diameters.transverse.push_back({force_pN, point.at("transverse_um").number()});
  }
  return diameters;
}

std::vector<svg::Series> mills_series() {
  const auto& mills = mills2004_stretch();
  Diameters diameters;
  for (std::size_t i = 0; i < mills.force_pN.size(); ++i) {
    diameters.axial.push_back({mills.force_pN[i], mills.axial_um[i], mills.axial_error_um[i]});
    diameters.transverse.push_back(
        {mills.force_pN[i], mills.transverse_um[i], mills.transverse_error_um[i]});
  }
  const std::string colour(svg::kReferenceColour);
  return {
      {"Mills et al. 2004, axial", diameters.axial, colour, svg::Marker::circle, false},
      {"Mills et al. 2004, transverse", diameters.transverse, colour, svg::Marker::square, false}};
}

// The morphology's own k_link (Table 2: 7 kBT for the discocyte, 11 for the aged cells, as its
// config overlay sets it); none for a morphology rbcsim does not know.
std::optional<double> table2_k_link_kBT(const std::string& morphology) {
  try {
    return config::resolve_config({.morphology = morphology}).number("membrane.k_link_kBT");
  } catch (const InputError&) {  // an unknown morphology: nothing to compare with
    return std::nullopt;
  }
}

// "discocyte, all six, quasi-static", then what departs from the morphology's default set-up
// (its Table 2 k_link, free contact patches), e.g. the parameters of calibrate's stretch fit:
// ", k_link 3.28 kBT, rigid patches". Config files of older versions may lack the members: they
// are optional.
std::string run_description(const RunDirectory& run) {
  auto description = morphology_and_terms(run) + ", " + run.section().at("mode").string();
  const auto config = run.config_field();
  const auto membrane = config.find("membrane");
  const auto k_link = membrane ? membrane->find("k_link_kBT") : std::nullopt;
  const auto table2_k_link = table2_k_link_kBT(run.morphology);
  if (k_link && table2_k_link && k_link->number() != *table2_k_link) {
    description += ", k_link " + format_significant(k_link->number(), 3) + " kBT";
  }
  const auto stretch = config.find("stretch");
  const auto contact = stretch ? stretch->find("contact") : std::nullopt;
  const auto rigid = contact ? contact->find("rigid") : std::nullopt;
  if (rigid && rigid->boolean()) description += ", rigid patches";
  return description;
}

}  // namespace

Section build_stretch_section(const RunList& all_runs) {
  Section section{"stretch", "Stretching (optical tweezers)", {}, nlohmann::json::array()};
  const auto drawn = plotted_runs(all_runs, section, has_converged_points);
  name_unfinished_runs(drawn,
                       "Drawn up to the last force that reached its steady shape, and left out of "
                       "the comparison and headline tables (not the whole curve)",
                       section);
  const auto drawn_labels = distinct_labels(drawn, run_description);

  svg::LinePlot plot{"Cell diameters vs stretching force", "force (pN)", "diameter (µm)", {}};
  std::vector<LabelledObject> comparisons;
  RunList runs;  // the finished ones
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const auto diameters = run_diameters(*drawn[i]);
    const auto colour = svg::palette_colour(i);
    const auto label = label_with_status(*drawn[i], drawn_labels[i]);
    plot.series.push_back({label + ", axial", diameters.axial, colour, svg::Marker::circle});
    plot.series.push_back(
        {label + ", transverse", diameters.transverse, colour, svg::Marker::square, true, true});
    if (!drawn[i]->succeeded()) continue;
    runs.push_back(drawn[i]);
    labels.push_back(drawn_labels[i]);
    if (const auto comparison = drawn[i]->section().find("comparison")) {
      comparisons.push_back({labels.back(), comparison->object()});
    }
    section.summary.push_back(run_summary(*drawn[i]));
  }
  // The measurements last, so they are drawn over the runs' lines.
  for (auto& series : mills_series()) plot.series.push_back(std::move(series));
  section.blocks.emplace_back(Figure{
      svg::render_line_plot(plot),
      "Axial (solid) and transverse (dashed) diameters at steady state against the total force "
      "on each contact patch. Black: Mills et al. (2004), Fig. 8, healthy cells, with error bars "
      "(half-lengths as digitised, share/reference/mills2004_stretch.csv)."});
  if (!comparisons.empty()) {
    section.blocks.emplace_back(
        table_of_objects("Comparison with Mills et al. (2004)", "run", comparisons));
  }
  section.blocks.emplace_back(headline_table(runs, labels));
  return section;
}

}  // namespace rbcsim::report
