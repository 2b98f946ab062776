// The report's suspension section: runs of `capillary --geometry tube --hematocrit` against the
// in-vitro fits of Pries et al., a mixture against discocytes alone, where the cells' centres sit,
// and a stopped run drawn but not compared.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "report/reference_data.hpp"
#include "report/report.hpp"
#include "report/run_fixtures.hpp"
#include "support/scratch_directory.hpp"
#include "support/xml_document.hpp"

namespace {

using rbcsim::report::build_report;
using rbcsim::report::pries1992_relative_apparent_viscosity;
using rbcsim::report::read_run_directories;
using rbcsim::testing::parse_xml;
using rbcsim::testing::suspension_run;
using rbcsim::testing::write_run;

std::vector<std::string> series_labels(const rbcsim::testing::XmlDocument& page) {
  std::vector<std::string> labels;
  for (const auto i : page.find("g", "series")) {
    labels.push_back(page.elements[i].attribute("data-label"));
  }
  return labels;
}

bool contains(const std::vector<std::string>& labels, const std::string& label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

// Discocytes 5 % above the fit at their measured H_D, a mixture 30 % above it: the verdict
// tells them apart, and the mixture is set beside the discocytes of the same tube and
// hematocrit.
TEST(SuspensionReport, ComparesEachRunWithPriesAndAMixtureWithDiscocytesAlone) {
  rbcsim::testing::ScratchDirectory scratch;
  const double fit = pries1992_relative_apparent_viscosity(20.0, 0.35);
  const auto plain = suspension_run(20.0, 0.30, 0.35, 1.05 * fit, {{"discocyte", 10, 3.0}});
  const auto mixed = suspension_run(20.0, 0.31, 0.35, 1.30 * fit,
                                    {{"discocyte", 7, 3.0}, {"echinocyte-III", 3, 7.5}});
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "plain", plain), write_run(scratch.path() / "mixed", mixed)}));
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");

  const auto& section = documents.summary.at("suspension");
  ASSERT_EQ(section.at("runs").size(), 2u);
  std::map<std::string, std::string> viscosity_verdicts;
  for (const auto& comparison : section.at("comparisons")) {
    const auto what = comparison.at("comparison").get<std::string>();
    if (what.ends_with("relative apparent viscosity")) {
      viscosity_verdicts[what] = comparison.at("verdict").get<std::string>();
    }
  }
  EXPECT_EQ(
      viscosity_verdicts,
      (std::map<std::string, std::string>{
          {"suspension D 20 um, H_T 0.3: 10 discocyte: relative apparent viscosity", "within 15 %"},
          {"suspension D 20 um, H_T 0.31: 7 discocyte + 3 echinocyte-III: relative apparent "
           "viscosity",
           "differs by more than 15 %"}}));
  // The verdict section carries every comparison of the suspension section.
  std::size_t suspension_rows = 0;
  for (const auto& row : documents.summary.at("verdict")) {
    if (row.at("comparison").get<std::string>().starts_with("suspension ")) ++suspension_rows;
  }
  EXPECT_EQ(suspension_rows, section.at("comparisons").size());

  ASSERT_EQ(section.at("mixtures").size(), 1u);
  const auto& mixture = section.at("mixtures")[0];
  EXPECT_NEAR(mixture.at("ratio").get<double>(), 1.30 / 1.05, 1e-12);
  EXPECT_TRUE(mixture.at("resolved_beyond_twice_the_spread").get<bool>());

  // Time plots for both runs, each diameter plot with the fits, and the centres of each
  // morphology of the mixture as a series of its own.
  const auto labels = series_labels(page);
  EXPECT_TRUE(contains(labels, "D 20 um, H_T 0.3: 10 discocyte: H_D"));
  EXPECT_TRUE(contains(labels, "Pries et al. 1992 in vitro, H_D 0.45"));
  EXPECT_TRUE(contains(labels, "Pries et al. 1990 at each run's measured H_D"));
  EXPECT_TRUE(
      contains(labels, "D 20 um, H_T 0.31: 7 discocyte + 3 echinocyte-III: echinocyte-III"));
}

// The centres' radial distribution is normalised by area: centres all in the outermost ring of
// ten show there as 1 / (its share of the cross-section, 1 - 0.9^2 = 0.19) and as 0 elsewhere;
// a morphology spread evenly over the rings' midpoints shows share of centres over share of area.
TEST(SuspensionReport, CentreDistributionIsRelativeToAnEvenSpread) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto run =
      suspension_run(20.0, 0.3, 0.35, 1.3, {{"discocyte", 4, 9.5}, {"stomatocyte-II", 2, 0.5}});
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "wall", run)}));
  const auto& density = documents.summary.at("suspension").at("runs")[0].at("centre_density");
  const auto rings = density.at("ring_midpoints_r_over_R").get<std::vector<double>>();
  ASSERT_EQ(rings.size(), 10u);
  EXPECT_DOUBLE_EQ(rings.front(), 0.05);
  EXPECT_DOUBLE_EQ(rings.back(), 0.95);
  const auto at_wall = density.at("discocyte").get<std::vector<double>>();
  const auto at_axis = density.at("stomatocyte-II").get<std::vector<double>>();
  for (std::size_t ring = 0; ring < 9; ++ring) EXPECT_EQ(at_wall[ring], 0.0) << ring;
  EXPECT_NEAR(at_wall[9], 1.0 / 0.19, 1e-12);
  EXPECT_NEAR(at_axis[0], 1.0 / 0.01, 1e-9);  // the innermost ring holds 1 % of the area
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");
  EXPECT_TRUE(contains(series_labels(page),
                       "D 20 um, H_T 0.3: 4 discocyte + 2 stomatocyte-II: "
                       "stomatocyte-II"));
}

// The hematocrit profile of result.json is drawn against the rings' midpoints over R; a run
// written before the profile existed has none and no curve.
TEST(SuspensionReport, HematocritProfileIsDrawnAgainstTheRingMidpoints) {
  rbcsim::testing::ScratchDirectory scratch;
  auto profiled = suspension_run(10.0, 0.2, 0.25, 1.2, {{"discocyte", 5, 2.0}});
  profiled.section["hematocrit_profile"] = {{"ring_inner_radius_um", {0.0, 2.5}},
                                            {"ring_outer_radius_um", {2.5, 5.0}},
                                            {"volume_fraction", {0.3, 0.1}}};
  const auto older = suspension_run(20.0, 0.2, 0.25, 1.2, {{"discocyte", 5, 2.0}});
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "profiled", profiled),
                                         write_run(scratch.path() / "older", older)}));
  const auto& runs = documents.summary.at("suspension").at("runs");
  ASSERT_EQ(runs.size(), 2u);
  for (const auto& run : runs) {
    const auto& profile = run.at("hematocrit_profile");
    if (run.at("label").get<std::string>().starts_with("D 20 um")) {
      EXPECT_TRUE(profile.is_null());
      continue;
    }
    EXPECT_EQ(profile.at("r_over_R"), (nlohmann::json{0.25, 0.75}));
    EXPECT_EQ(profile.at("volume_fraction"), (nlohmann::json{0.3, 0.1}));
  }
  EXPECT_NE(documents.html.find("Hematocrit across the tube"), std::string::npos);
}

// A run in which cells passed through each other keeps its numbers but gets no verdict.
TEST(SuspensionReport, PiercedCellsWithholdTheVerdict) {
  rbcsim::testing::ScratchDirectory scratch;
  auto run = suspension_run(10.0, 0.2, 0.25, 1.13, {{"discocyte", 5, 2.0}});
  run.section["samples_with_pierced_cells"] = 16;
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "pierced", run)}));
  const auto& comparisons = documents.summary.at("suspension").at("comparisons");
  ASSERT_EQ(comparisons.size(), 2u);
  for (const auto& comparison : comparisons) {
    EXPECT_EQ(comparison.at("verdict"), "not a result: cells pierced each other in 16 samples");
  }
}

// A flow that has not yet carried its cells 25 tube diameters (the lower end of the 25-50 that a
// packing needs to develop, Chien et al.) keeps its numbers but gets no verdict; a run written
// before the travel was recorded gets it from its cells' centroids, or no verdict without them.
// At 25 it is compared.
TEST(SuspensionReport, UndevelopedFlowWithholdsTheVerdict) {
  rbcsim::testing::ScratchDirectory scratch;
  auto short_run = suspension_run(20.0, 0.3, 0.35, 1.3, {{"discocyte", 5, 2.0}});
  short_run.section["cell_travel_um"] = 7.0;
  short_run.section["cell_travel_tube_diameters"] = 0.35;
  auto older = suspension_run(10.0, 0.3, 0.35, 1.3, {{"discocyte", 5, 2.0}});
  older.section.erase("cell_travel_um");
  older.section.erase("cell_travel_tube_diameters");
  // An older run whose cells' time series has their centroids: the travel comes from there,
  // 20 and 40 um in a 30 um tube, one diameter.
  auto older_with_centroids = suspension_run(30.0, 0.3, 0.35, 1.3, {{"discocyte", 2, 2.0}});
  older_with_centroids.section.erase("cell_travel_um");
  older_with_centroids.section.erase("cell_travel_tube_diameters");
  older_with_centroids.files["cells_timeseries.csv"] =
      "time_s,cell_id,morphology_index,radial_position_um,centroid_x_um\n"
      "0,0,0,2,1\n0,1,0,2,5\n0.001,0,0,2,21\n0.001,1,0,2,45\n";
  auto developed = suspension_run(40.0, 0.3, 0.35, 1.3, {{"discocyte", 5, 2.0}});
  developed.section["cell_travel_um"] = 25.0 * 40.0;
  developed.section["cell_travel_tube_diameters"] = 25.0;
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "short", short_run), write_run(scratch.path() / "older", older),
       write_run(scratch.path() / "centroids", older_with_centroids),
       write_run(scratch.path() / "developed", developed)}));
  std::map<std::string, std::set<std::string>> verdicts;  // by tube diameter
  for (const auto& comparison : documents.summary.at("suspension").at("comparisons")) {
    const auto what = comparison.at("comparison").get<std::string>();
    verdicts[what.substr(0, what.find(" um"))].insert(comparison.at("verdict").get<std::string>());
  }
  EXPECT_EQ(verdicts.at("suspension D 20"),
            (std::set<std::string>{"not developed: the cells travelled 0.35 tube diameters of the "
                                   "25-50 a packing needs (Chien et al.)"}));
  EXPECT_EQ(
      verdicts.at("suspension D 10"),
      (std::set<std::string>{"not a result: how far the flow carried the cells was not recorded"}));
  EXPECT_EQ(verdicts.at("suspension D 30"),
            (std::set<std::string>{"not developed: the cells travelled 1 tube diameters of the "
                                   "25-50 a packing needs (Chien et al.)"}));
  for (const auto& verdict : verdicts.at("suspension D 40")) {
    EXPECT_FALSE(verdict.starts_with("not ")) << verdict;
  }
}

// A run that failed is drawn dashed in the time plots and left out of the comparisons.
TEST(SuspensionReport, StoppedRunIsDrawnButNotCompared) {
  rbcsim::testing::ScratchDirectory scratch;
  auto failed = suspension_run(10.0, 0.3, 0.4, 1.3, {{"discocyte", 3, 2.0}});
  failed.status = "failed";
  const auto ok = suspension_run(20.0, 0.3, 0.4, 1.3, {{"discocyte", 10, 3.0}});
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "failed", failed), write_run(scratch.path() / "ok", ok)}));
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");
  const auto& section = documents.summary.at("suspension");
  ASSERT_EQ(section.at("runs").size(), 1u);
  EXPECT_EQ(section.at("runs")[0].at("label"), "D 20 um, H_T 0.3: 10 discocyte");
  for (const auto& comparison : section.at("comparisons")) {
    EXPECT_EQ(comparison.at("comparison").get<std::string>().find("D 10 um"), std::string::npos);
  }
  EXPECT_TRUE(contains(series_labels(page), "D 10 um, H_T 0.3: 3 discocyte (failed)"));
  EXPECT_NE(documents.html.find("left out of the averages and comparisons: " +
                                (scratch.path() / "failed").generic_string()),
            std::string::npos);
}

}  // namespace
