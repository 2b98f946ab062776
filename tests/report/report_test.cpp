#include "report/report.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/errors.hpp"
#include "report/run_fixtures.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"
#include "support/xml_document.hpp"

namespace {

using rbcsim::report::build_report;
using rbcsim::report::read_run_directories;
using rbcsim::testing::parse_xml;
using rbcsim::testing::XmlDocument;

class ReportOfStandardRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    directories_ = rbcsim::testing::write_standard_runs(scratch_.path());
    documents_ = build_report(read_run_directories(directories_));
    page_ = parse_xml(documents_.html);
    ASSERT_EQ(page_.error, "") << "report.html is not well-formed XML";
  }

  // The <svg> whose <title> is `title`; fails the test if there is none.
  long figure(const std::string& title) const {
    for (const auto i : page_.find("title")) {
      const auto parent = page_.elements[i].parent;
      if (parent >= 0 && page_.elements[parent].name == "svg" && page_.elements[i].text == title) {
        return parent;
      }
    }
    ADD_FAILURE() << "no plot titled " << title;
    return -1;
  }

  // Texts of the <text> elements inside `ancestor`.
  std::vector<std::string> texts(long ancestor) const {
    std::vector<std::string> result;
    for (const auto i : page_.find("text", "", ancestor)) result.push_back(page_.elements[i].text);
    return result;
  }

  static bool contains(const std::vector<std::string>& items, const std::string& item) {
    return std::find(items.begin(), items.end(), item) != items.end();
  }

  rbcsim::testing::ScratchDirectory scratch_;
  std::vector<std::filesystem::path> directories_;
  rbcsim::report::ReportDocuments documents_;
  XmlDocument page_;
};

// The verdict first, the experiments in the paper's order, the runs' details last.
TEST_F(ReportOfStandardRuns, OpensWithTheVerdictThenOneSectionPerExperimentThenTheRuns) {
  std::vector<std::string> ids;
  for (const auto i : page_.find("section")) ids.push_back(page_.elements[i].attribute("id"));
  EXPECT_EQ(ids, (std::vector<std::string>{"verdict", "calibrate", "stretch", "shear", "capillary",
                                           "runs"}));
  // Every experiment of the standard runs with a reference has a row: the paper's moduli, Mills'
  // points, the capillary's DI after the throat.
  const auto& verdict = documents_.summary.at("verdict");
  auto has_row = [&verdict](const std::string& start) {
    return std::any_of(verdict.begin(), verdict.end(), [&start](const auto& row) {
      return row.at("comparison").template get<std::string>().starts_with(start);
    });
  };
  EXPECT_TRUE(has_row("calibrate discocyte, all six"));
  EXPECT_TRUE(has_row("stretch "));
  EXPECT_TRUE(has_row("capillary "));
  EXPECT_EQ(page_.find("script").size(), 0u);  // no JavaScript
  EXPECT_EQ(page_.find("link").size(), 0u);    // no external style sheet
  EXPECT_EQ(page_.find("img").size(), 0u);     // no external image
}

TEST_F(ReportOfStandardRuns, StretchPlotHasMillsWithErrorBarsAndBothTermSets) {
  const auto plot = figure("Cell diameters vs stretching force");
  const auto series = page_.labels("series", plot);
  // The measurements last: drawn over the runs.
  EXPECT_EQ(series,
            (std::vector<std::string>{
                "discocyte, all six, quasi-static, axial",
                "discocyte, all six, quasi-static, transverse",
                "discocyte, without area_difference and total_curvature, quasi-static, axial",
                "discocyte, without area_difference and total_curvature, quasi-static, "
                "transverse",
                "Mills et al. 2004, axial",
                "Mills et al. 2004, transverse",
            }));
  // 13 forces, an axial and a transverse error bar each, all from the reference data.
  EXPECT_EQ(page_.find("path", "error-bar", plot).size(), 26u);
  EXPECT_EQ(page_.labels("legend-entry", plot), series);
  const auto labels = texts(plot);
  EXPECT_TRUE(contains(labels, "force (pN)"));
  EXPECT_TRUE(contains(labels, "diameter (µm)"));
}

TEST_F(ReportOfStandardRuns, ShearHasALengthPlotPerMorphologyWithEachTermSet) {
  const auto discocyte = figure("Cell length vs shear rate: discocyte");
  EXPECT_EQ(page_.labels("series", discocyte), (std::vector<std::string>{"all six"}));
  for (const std::string morphology : {"echinocyte-III", "stomatocyte-II"}) {
    const auto plot = figure("Cell length vs shear rate: " + morphology);
    EXPECT_EQ(page_.labels("series", plot),
              (std::vector<std::string>{"all six", "without area_difference and total_curvature"}))
        << morphology;
    EXPECT_TRUE(contains(texts(plot), "shear rate (1/s)"));
    EXPECT_TRUE(contains(texts(plot), "cell length (µm)"));
    // Five rates per run, a marker each.
    EXPECT_EQ(page_.find("", "marker", page_.find("g", "series", plot)[0]).size(), 5u);
  }
  figure("Deformation index vs shear rate");
  figure("Surface smoothness vs shear rate");
  figure("Surface roughness vs shear rate");
}

TEST_F(ReportOfStandardRuns, CapillaryHasDeformationOverTimeAndTransitBars) {
  // Runs through two tubes: each label names its tube.
  const std::vector<std::string> runs{
      "discocyte, all six, paper-morphology", "discocyte, all six, paper-validation",
      "discocyte, without area_difference and total_curvature, paper-validation",
      "echinocyte-III, all six, paper-morphology", "stomatocyte-II, all six, paper-morphology"};
  const auto deformation = figure("Deformation index vs time");
  EXPECT_EQ(page_.labels("series", deformation), runs);
  // 41 samples of the time series, one polyline of 41 points per run.
  const auto line = page_.find("polyline", "", page_.find("g", "series", deformation)[0]);
  ASSERT_EQ(line.size(), 1u);
  const auto points = page_.elements[line[0]].attribute("points");
  EXPECT_EQ(std::count(points.begin(), points.end(), ' ') + 1, 41);
  const auto bars = figure("Transit time through the narrow section");
  EXPECT_EQ(page_.labels("bar", bars), runs);
}

TEST_F(ReportOfStandardRuns, SummaryJsonHasTheRunsNumbers) {
  const auto& summary = documents_.summary;
  EXPECT_EQ(summary.at("run_count"), 13);
  ASSERT_EQ(summary.at("runs").size(), 13u);
  EXPECT_EQ(summary.at("runs")[0].at("command"), "calibrate");
  EXPECT_EQ(summary.at("runs")[0].at("wall_time_s"), 2.5);

  const auto& calibrate = summary.at("calibrate").at(0).at("calibrate");
  EXPECT_EQ(calibrate.at("hexagonal").at("E_s_uN_per_m"), 29.7);

  const auto& stretch = summary.at("stretch");
  ASSERT_EQ(stretch.size(), 2u);
  EXPECT_EQ(stretch[0].at("terms"), "all six");
  EXPECT_EQ(stretch[0].at("stretch").at("comparison").at("rms_axial_um"), 0.31);
  EXPECT_EQ(stretch[1].at("terms"), "without area_difference and total_curvature");
  EXPECT_EQ(stretch[1].at("stretch").at("comparison").at("rms_axial_um"), 0.52);

  const auto& shear = summary.at("shear");
  ASSERT_EQ(shear.size(), 5u);
  EXPECT_EQ(shear[0].at("morphology"), "discocyte");
  EXPECT_EQ(shear[0].at("shear").at("rates").back().at("length_um"), 11.0);

  const auto& capillary = summary.at("capillary");
  EXPECT_EQ(capillary.at("runs")[4].at("morphology"), "stomatocyte-II");
  EXPECT_EQ(capillary.at("runs")[4].at("capillary").at("transit_time_s"), 1.5e-3);
  // One order: the validation tube's lone discocyte is neither ordered nor mixed into it.
  const auto& order = capillary.at("transit_time_order");
  ASSERT_EQ(order.size(), 1u);
  EXPECT_EQ(order[0].at("geometry"), "paper-morphology");
  EXPECT_EQ(order[0].at("order"),
            (std::vector<std::string>{"discocyte", "echinocyte-III", "stomatocyte-II"}));
  EXPECT_TRUE(order[0].at("agrees_with_paper"));
  // The discocyte through the validation tube with and without F_ad/F_tc: peak DI 2.0 and 2.1.
  const auto& peaks = capillary.at("peak_deformation_index_by_terms");
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_EQ(peaks[0].at("geometry"), "paper-validation");
  EXPECT_EQ(peaks[0].at("all_six_peak_deformation_index"), 2.0);
  EXPECT_EQ(peaks[0].at("peak_deformation_index"), 2.1);
  EXPECT_TRUE(peaks[0].at("lower_with_all_six"));
}

TEST_F(ReportOfStandardRuns, CalibrationTableShowsOwnAndPaperValues) {
  const auto& markdown = documents_.markdown;
  EXPECT_NE(markdown.find("| hexagonal | E\\_s (µN/m) | 29.7 | 29.85 |"), std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| two\\_triangle | bending\\_modulus (J) | 2.05e-19 | 2e-19 |"),
            std::string::npos);
  // A quantity the paper object does not give.
  EXPECT_NE(markdown.find("| hexagonal | k\\_link (kBT) | 7 | — |"), std::string::npos);
  // A group inside a test: one row per quantity, not the group's JSON.
  EXPECT_NE(markdown.find("| stretch\\_fit | comparison: rms\\_axial (µm) | 0.59 | — |"),
            std::string::npos)
      << markdown;
}

TEST_F(ReportOfStandardRuns, MarkdownHasTheHeadlineTablesButNoFigures) {
  const auto& markdown = documents_.markdown;
  EXPECT_EQ(markdown.find("<svg"), std::string::npos);
  EXPECT_NE(markdown.find("## Stretching (optical tweezers)"), std::string::npos);
  EXPECT_NE(
      markdown.find("| discocyte, all six, quasi-static | 11 | 13 | mills2004 | 0.31 | 0.25 |"),
      std::string::npos)
      << markdown;
  EXPECT_NE(
      markdown.find(
          "Transit time order, all six, paper-morphology: discocyte (0.001 s) \\< echinocyte-III "
          "(0.0012 s) \\< stomatocyte-II (0.0015 s). The paper finds discocyte \\< "
          "echinocyte III \\< stomatocyte II: same order."),
      std::string::npos);
  EXPECT_NE(markdown.find("Peak DI, discocyte, paper-validation: 2 with all six terms, 2.1 without "
                          "area\\_difference and total\\_curvature (lower with F\\_ad and "
                          "F\\_tc; the paper's Fig. 13 has it lower with them)."),
            std::string::npos)
      << markdown;
}

TEST_F(ReportOfStandardRuns, RunsTableListsEveryRunWithItsMetadata) {
  const auto& markdown = documents_.markdown;
  const auto directory = (scratch_.path() / "stretch-four").generic_string();
  // Underscores and other Markdown punctuation come escaped.
  std::string escaped;
  for (const char c : directory) {
    if (c == '_') escaped += '\\';
    escaped += c;
  }
  EXPECT_NE(markdown.find("| " + escaped +
                          " | stretch | discocyte | paper | without area\\_difference and "
                          "total\\_curvature | ok | 2.5 | " RBCSIM_VERSION " | 2 |"),
            std::string::npos)
      << markdown;
  // The full configuration of each run, folded, with the run's metadata.
  EXPECT_EQ(page_.find("details").size(), 13u);
  const auto configuration = page_.find("details")[2];
  std::vector<std::string> cells;
  for (const auto i : page_.find("td", "", static_cast<long>(configuration))) {
    cells.push_back(page_.elements[i].text);
  }
  for (const std::string expected :
       {"run.started_utc", "2024-05-01T12:00:00Z", "run.mesh_source", "built-in discocyte",
        "membrane.forces", "link, bend, area, volume"}) {
    EXPECT_NE(std::find(cells.begin(), cells.end(), expected), cells.end()) << expected;
  }
}

TEST_F(ReportOfStandardRuns, OutputDoesNotDependOnArgumentOrder) {
  auto reversed = directories_;
  std::reverse(reversed.begin(), reversed.end());
  const auto again = build_report(read_run_directories(reversed));
  EXPECT_EQ(again.html, documents_.html);
  EXPECT_EQ(again.markdown, documents_.markdown);
  EXPECT_EQ(again.summary, documents_.summary);
}

TEST_F(ReportOfStandardRuns, WritesTheThreeFilesIdenticallyTwice) {
  const auto output = scratch_.path() / "out";
  const auto files = rbcsim::report::write_report(documents_, output);
  ASSERT_EQ(files.size(), 3u);
  std::vector<std::string> first;
  for (const auto& file : files) first.push_back(rbcsim::testing::read_text(file));
  rbcsim::report::write_report(build_report(read_run_directories(directories_)), output);
  for (std::size_t i = 0; i < files.size(); ++i) {
    EXPECT_EQ(rbcsim::testing::read_text(files[i]), first[i]) << files[i];
  }
  EXPECT_EQ(first[0], documents_.html);
  EXPECT_EQ(nlohmann::json::parse(first[2]), documents_.summary);
  // Nothing but the three files: no temporary left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(output), {}), 3);
}

}  // namespace
