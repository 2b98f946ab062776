// Optical-tweezers stretching (DESIGN.md §4 stretch): axial and transverse diameters against
// force for every run, over the Mills et al. (2004) measurements with their error bars.
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

Diameters run_diameters(const RunDirectory& run) {
  const auto points = run.section().at("points");
  Diameters diameters;
  for (std::size_t i = 0; i < points.array_size(); ++i) {
    const auto point = points.at(i);
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
  const auto runs = plotted_runs(all_runs, section);
  const auto labels = distinct_labels(runs, run_description);

  svg::LinePlot plot{"Cell diameters vs stretching force", "force (pN)", "diameter (µm)", {}};
  std::vector<LabelledObject> comparisons;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto diameters = run_diameters(*runs[i]);
    const auto colour = svg::palette_colour(i);
    plot.series.push_back({labels[i] + ", axial", diameters.axial, colour, svg::Marker::circle});
    plot.series.push_back({labels[i] + ", transverse", diameters.transverse, colour,
                           svg::Marker::square, true, true});
    const auto stretch = runs[i]->section();
    if (const auto comparison = stretch.find("comparison")) {
      comparisons.push_back({labels[i], comparison->object()});
    }
    section.summary.push_back(run_summary(*runs[i]));
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
