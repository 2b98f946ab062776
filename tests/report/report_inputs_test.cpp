// What the report does with awkward input: hostile strings, failed runs, other commands, and
// run directories that break the contract (each must name the file and the problem).
#include <gtest/gtest.h>

#include <map>

#include "common/errors.hpp"
#include "membrane/parameters.hpp"
#include "report/report.hpp"
#include "report/run_directory.hpp"
#include "report/run_fixtures.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"
#include "support/xml_document.hpp"

namespace {

using rbcsim::report::build_report;
using rbcsim::report::read_run_directories;
using rbcsim::testing::FixtureRun;
using rbcsim::testing::parse_xml;
using rbcsim::testing::write_file;
using rbcsim::testing::write_run;

// Term sets are named relative to the paper's six; a term beyond them is appended.
TEST(DescribeTerms, NamesATermSetRelativeToThePapersSix) {
  using rbcsim::report::describe_terms;
  const auto paper = rbcsim::membrane::paper_force_term_names();
  EXPECT_EQ(describe_terms(paper), "all six");
  auto with_total_area = paper;
  with_total_area.push_back("total_area");
  EXPECT_EQ(describe_terms(with_total_area), "all six + total_area");
  EXPECT_EQ(describe_terms({"link", "bend", "area", "volume", "total_area"}),
            "without area_difference and total_curvature, with total_area");
  EXPECT_EQ(describe_terms({"total_area"}), "none of the paper's, with total_area");
  // The physiological preset's: Helfrich's bending in place of the paper's.
  EXPECT_EQ(describe_terms({"link", "helfrich", "area", "volume", "area_difference",
                            "total_curvature", "total_area", "local_area", "viscosity"}),
            "without bend, with helfrich, total_area, local_area and viscosity");
  EXPECT_EQ(describe_terms({"link", "springs"}), "link and springs");
}

// The message of the InputError that building the report of `directories` throws.
std::string report_error(const std::vector<std::filesystem::path>& directories) {
  try {
    build_report(read_run_directories(directories));
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "no error";
}

// The paper's moduli are an isolated patch's: the verdict compares that with them, and names the
// tiled sheet's (the cell's membrane) as such instead of passing it off as the same test.
TEST(ReportInputs, TheVerdictComparesTheIsolatedPatchWithThePapersModuli) {
  rbcsim::testing::ScratchDirectory scratch;
  auto calibrate = rbcsim::testing::calibrate_run();
  calibrate.section["hexagonal"]["mu_uN_per_m"] = 7.34;
  calibrate.section["hexagonal"]["isolated_patch_mu_uN_per_m"] = 9.9;
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "calibrate", calibrate)}));
  std::map<std::string, std::string> verdicts;
  for (const auto& row : documents.summary.at("verdict")) {
    verdicts[row.at("comparison").get<std::string>()] = row.at("verdict").get<std::string>();
  }
  EXPECT_EQ(verdicts["calibrate discocyte, all six: hexagonal, isolated patch (the paper's "
                     "set-up): mu (µN/m)"],
            "agrees");  // 9.9 against 10.15: 2.5 %
  EXPECT_EQ(
      verdicts
          ["calibrate discocyte, all six: hexagonal, tiled sheet (the cell's membrane): mu (µN/m)"],
      "differs");
  EXPECT_EQ(
      verdicts
          ["calibrate discocyte, all six: hexagonal, tiled sheet (the cell's membrane): K (µN/m)"],
      "agrees");
}

TEST(ReportInputs, HostileStringsAreEscapedEverywhere) {
  rbcsim::testing::ScratchDirectory scratch;
  const std::string morphology = "<script>alert(\"x\")</script> & 'q' ]]> \x01 |*_";
  const std::vector<std::string> forces{"link", "<b>bold</b>"};
  auto stretch = rbcsim::testing::stretch_run(forces, 90, 0.3);
  stretch.morphology = morphology;
  auto capillary = rbcsim::testing::capillary_run(morphology, 1e-3, 1.4);
  capillary.forces = forces;
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "stretch", stretch),
                                         write_run(scratch.path() / "capillary", capillary)}));

  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");
  EXPECT_EQ(page.find("script").size(), 0u);
  EXPECT_EQ(page.find("b").size(), 0u);
  // The parser reads back the text as written, the control character (which XML cannot carry)
  // replaced by U+FFFD.
  const std::string shown = "<script>alert(\"x\")</script> & 'q' ]]> \xEF\xBF\xBD |*_";
  const std::string terms = "link and <b>bold</b>";
  std::vector<std::string> series;
  for (const auto i : page.find("g", "series"))
    series.push_back(page.elements[i].attribute("data-label"));
  EXPECT_NE(std::find(series.begin(), series.end(), shown + ", " + terms + ", quasi-static, axial"),
            series.end());
  EXPECT_NE(std::find(series.begin(), series.end(), shown + ", " + terms), series.end());

  // Markdown: one line per row, no raw tag, no unescaped cell separator.
  EXPECT_EQ(documents.markdown.find("<script>"), std::string::npos);
  EXPECT_EQ(documents.markdown.find("\x01"), std::string::npos);
  EXPECT_NE(documents.markdown.find("\\</script\\> & 'q' \\]\\]\\>   \\|\\*\\_"), std::string::npos)
      << documents.markdown;
  // summary.json keeps the strings exactly.
  EXPECT_EQ(documents.summary.at("stretch")[0].at("morphology"), morphology);
  EXPECT_EQ(documents.summary.at("stretch")[0].at("terms"), terms);
}

TEST(ReportInputs, FailedAndInterruptedRunsAreListedButNotPlotted) {
  rbcsim::testing::ScratchDirectory scratch;
  // Both stopped before their first force reached its steady shape: nothing to draw.
  auto failed = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 90, 0.3);
  failed.status = "failed";
  // json::array: a braced list of one json is a copy for clang and an array for GCC.
  failed.section["points"] = nlohmann::json::array({failed.section["points"][0]});
  failed.section["points"][0]["converged"] = false;
  auto interrupted = rbcsim::testing::stretch_run(rbcsim::testing::four_terms(), 90, 0.3);
  interrupted.status = "interrupted";
  interrupted.section["points"] = nlohmann::json::array();
  auto ok = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 80, 0.2);
  ok.morphology = "echinocyte-III";
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "failed", failed),
                                         write_run(scratch.path() / "interrupted", interrupted),
                                         write_run(scratch.path() / "ok", ok)}));
  EXPECT_EQ(documents.summary.at("runs").size(), 3u);
  ASSERT_EQ(documents.summary.at("stretch").size(), 1u);
  EXPECT_EQ(documents.summary.at("stretch")[0].at("morphology"), "echinocyte-III");
  EXPECT_NE(documents.html.find("Failed or interrupted runs (listed under Runs, not plotted): " +
                                (scratch.path() / "failed").generic_string() + ", " +
                                (scratch.path() / "interrupted").generic_string() + "."),
            std::string::npos);
  const auto page = parse_xml(documents.html);
  for (const auto i : page.find("g", "series")) {
    EXPECT_EQ(page.elements[i].attribute("data-label").find("discocyte"), std::string::npos);
  }
}

// What a run told the user when it started (config.json run.notices) is in the Runs section
// under the run's name and in summary.json; a run without notices gets neither.
TEST(ReportInputs, RunNoticesAreShownUnderRuns) {
  rbcsim::testing::ScratchDirectory scratch;
  auto coarse = rbcsim::testing::capillary_run("echinocyte-III", 1.6e-3, 2.1);
  coarse.notices = {"the mesh does not resolve the spicules", "edges < spacing & more"};
  const auto plain = rbcsim::testing::capillary_run("discocyte", 1.4e-3, 2.2);
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "coarse", coarse), write_run(scratch.path() / "plain", plain)}));
  ASSERT_EQ(parse_xml(documents.html).error, "");
  const auto coarse_name = (scratch.path() / "coarse").generic_string();
  EXPECT_NE(
      documents.html.find("Notice of " + coarse_name + ": the mesh does not resolve the spicules."),
      std::string::npos);
  EXPECT_NE(documents.html.find("Notice of " + coarse_name + ": edges &lt; spacing &amp; more."),
            std::string::npos);
  EXPECT_EQ(documents.html.find("Notice of " + (scratch.path() / "plain").generic_string()),
            std::string::npos);
  ASSERT_EQ(documents.summary.at("runs").size(), 2u);
  for (const auto& run : documents.summary.at("runs")) {  // in the report's order of runs
    const bool is_coarse = run.at("morphology") == "echinocyte-III";
    EXPECT_EQ(run.at("notices"),
              is_coarse ? nlohmann::json(coarse.notices) : nlohmann::json::array());
  }
}

// A notice several runs got is one line naming them all, not one line per run.
TEST(ReportInputs, ANoticeSharedByRunsIsOneLineNamingThem) {
  rbcsim::testing::ScratchDirectory scratch;
  auto first = rbcsim::testing::capillary_run("echinocyte-III", 1.6e-3, 2.1);
  auto second = rbcsim::testing::capillary_run("discocyte", 1.4e-3, 2.2);
  first.notices = {"shared notice", "own notice"};
  second.notices = {"shared notice"};
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "a", first), write_run(scratch.path() / "b", second)}));
  ASSERT_EQ(parse_xml(documents.html).error, "");
  const auto a = (scratch.path() / "a").generic_string();
  const auto b = (scratch.path() / "b").generic_string();
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string chains.
  std::string shared = "Notice of ";  // the runs in the report's order: by morphology
  shared.append(b).append(", ").append(a).append(": shared notice.");
  const auto at = documents.html.find(shared);
  EXPECT_NE(at, std::string::npos);
  for (const auto& alone : {a, b}) {  // no line of its own for either run
    std::string single = "Notice of ";
    single.append(alone).append(": shared notice.");
    EXPECT_EQ(documents.html.find(single), std::string::npos);
  }
  std::string own = "Notice of ";
  own.append(a).append(": own notice.");
  EXPECT_NE(documents.html.find(own), std::string::npos);
}

// A capillary run that stopped is drawn up to where it stopped (where a cell fails is worth
// seeing), dashed and marked, but it has no transit: no bar, no row, no summary entry. One that
// stopped before writing its time series is only listed.
TEST(ReportInputs, CapillaryRunThatStoppedIsDrawnUpToItsStopWithoutATransit) {
  rbcsim::testing::ScratchDirectory scratch;
  auto failed = rbcsim::testing::capillary_run("discocyte", 1.4e-3, 2.2);
  failed.status = "failed";
  auto no_series = rbcsim::testing::capillary_run("stomatocyte-II", 1.5e-3, 2.0);
  no_series.status = "interrupted";
  no_series.time_series_csv.clear();
  const auto ok = rbcsim::testing::capillary_run("echinocyte-III", 1.6e-3, 2.1);
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "failed", failed),
       write_run(scratch.path() / "no-series", no_series), write_run(scratch.path() / "ok", ok)}));
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");

  ASSERT_EQ(documents.summary.at("capillary").at("runs").size(), 1u);
  EXPECT_EQ(documents.summary.at("capillary").at("runs")[0].at("morphology"), "echinocyte-III");
  EXPECT_NE(documents.html.find("not plotted): " + (scratch.path() / "no-series").generic_string()),
            std::string::npos);
  EXPECT_NE(documents.html.find("up to where they stopped, and left out of the transit times and "
                                "tables (no transit): " +
                                (scratch.path() / "failed").generic_string() + "."),
            std::string::npos);
  std::vector<std::string> series;
  std::vector<std::string> dashes;
  for (const auto i : page.find("g", "series")) {
    series.push_back(page.elements[i].attribute("data-label"));
    const auto lines = page.find("polyline", "", static_cast<long>(i));
    ASSERT_EQ(lines.size(), 1u);
    dashes.push_back(page.elements[lines[0]].attribute("stroke-dasharray"));
  }
  EXPECT_EQ(series,
            (std::vector<std::string>{"discocyte, all six (failed)", "echinocyte-III, all six"}));
  EXPECT_EQ(dashes, (std::vector<std::string>{"6 4", ""}));
  std::vector<std::string> bars;
  for (const auto i : page.find("g", "bar"))
    bars.push_back(page.elements[i].attribute("data-label"));
  EXPECT_EQ(bars, std::vector<std::string>{"echinocyte-III, all six"});
}

// A stretch that failed at its ninth force (the paper's pairing in fluid) is drawn up to its
// eighth, marked, and left out of the comparison with Mills: it is not the whole curve.
TEST(ReportInputs, StretchThatFailedIsDrawnUpToItsLastSteadyForce) {
  rbcsim::testing::ScratchDirectory scratch;
  auto failed = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 90, 0.3);
  failed.status = "failed";
  auto& points = failed.section["points"];
  points.erase(points.begin() + 9, points.end());  // 0 .. 109 pN
  points[8]["converged"] = false;                  // failed at 109 pN
  auto ok = rbcsim::testing::stretch_run(rbcsim::testing::four_terms(), 80, 0.2);
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "failed", failed), write_run(scratch.path() / "ok", ok)}));
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");

  std::vector<std::string> series;
  std::vector<std::size_t> marker_counts;
  for (const auto i : page.find("g", "series")) {
    series.push_back(page.elements[i].attribute("data-label"));
    marker_counts.push_back(page.find("", "marker", static_cast<long>(i)).size());
  }
  ASSERT_EQ(series.size(), 6u);  // two runs and Mills, axial and transverse each
  EXPECT_EQ(series[0], "discocyte, all six, quasi-static (failed), axial");
  EXPECT_EQ(marker_counts[0], 8u);
  EXPECT_EQ(marker_counts[1], 8u);
  EXPECT_EQ(series[2],
            "discocyte, without area_difference and total_curvature, quasi-static, axial");
  EXPECT_EQ(marker_counts[2], 13u);
  ASSERT_EQ(documents.summary.at("stretch").size(), 1u);
  EXPECT_EQ(documents.summary.at("stretch")[0].at("terms"),
            "without area_difference and total_curvature");
  EXPECT_NE(documents.html.find("left out of the comparison and headline tables (not the whole "
                                "curve): " +
                                (scratch.path() / "failed").generic_string() + "."),
            std::string::npos);
  EXPECT_EQ(documents.markdown.find("quasi-static (failed) |"), std::string::npos);
}

// A sweep that failed at its highest rate keeps the rates below it: they finished, and the
// failure is the finding (the paper's "unnatural deformations" without F_ad and F_tc).
TEST(ReportInputs, ShearSweepThatFailedAtARatePlotsTheRatesThatFinished) {
  rbcsim::testing::ScratchDirectory scratch;
  auto partial = rbcsim::testing::shear_run("stomatocyte-II", rbcsim::testing::four_terms(), 11);
  partial.status = "failed";
  partial.section["rates"][4]["failure"] = "step 9755: edge 867 beyond its limit";
  partial.section["rates"][4]["steady"] = false;
  auto nothing_finished =
      rbcsim::testing::shear_run("echinocyte-III", rbcsim::testing::all_terms(), 10);
  nothing_finished.status = "interrupted";
  for (auto& rate : nothing_finished.section["rates"]) rate["failure"] = "interrupted";
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "partial", partial),
                                         write_run(scratch.path() / "nothing", nothing_finished)}));
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");

  ASSERT_EQ(documents.summary.at("shear").size(), 1u);
  EXPECT_EQ(documents.summary.at("shear")[0].at("morphology"), "stomatocyte-II");
  EXPECT_NE(documents.html.find("not plotted): " + (scratch.path() / "nothing").generic_string()),
            std::string::npos);
  EXPECT_NE(documents.html.find("not in the plots: stomatocyte-II, without area_difference and "
                                "total_curvature: 2000 1/s."),
            std::string::npos)
      << documents.markdown;
  // Four of the five rates in the length plot; all five, with the failure, in the sweep's table.
  long plot = -1;
  for (const auto i : page.find("title")) {
    if (page.elements[i].text == "Cell length vs shear rate: stomatocyte-II") {
      plot = page.elements[i].parent;
    }
  }
  ASSERT_GE(plot, 0);
  const auto series = page.find("g", "series", plot);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(page.find("", "marker", static_cast<long>(series[0])).size(), 4u);
  EXPECT_NE(documents.markdown.find("| 2000 |"), std::string::npos);
  EXPECT_NE(documents.markdown.find("step 9755: edge 867 beyond its limit"), std::string::npos);
}

TEST(ReportInputs, OtherCommandsGetTheirHeadlineNumbers) {
  rbcsim::testing::ScratchDirectory scratch;
  FixtureRun bench{.command = "bench"};
  bench.headline = {{"fluid_mlups", 61.5}};
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "bench", bench)}));
  EXPECT_EQ(documents.summary.at("other-1").at("command"), "bench");
  EXPECT_EQ(documents.summary.at("other-1").at("runs")[0].at("headline").at("fluid_mlups"), 61.5);
  EXPECT_NE(documents.markdown.find("## Other runs: bench"), std::string::npos);
  EXPECT_EQ(parse_xml(documents.html).error, "");
}

TEST(ReportInputs, RunsThatWouldShareALabelAreToldApartByDirectory) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto run = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 90, 0.3);
  const auto first = write_run(scratch.path() / "first", run);
  const auto second = write_run(scratch.path() / "second", run);
  const auto page = parse_xml(build_report(read_run_directories({first, second})).html);
  std::vector<std::string> series;
  for (const auto i : page.find("g", "series"))
    series.push_back(page.elements[i].attribute("data-label"));
  ASSERT_EQ(series.size(), 6u);
  EXPECT_EQ(series[0], "discocyte, all six, quasi-static (" + first.generic_string() + "), axial");
  EXPECT_EQ(series[2], "discocyte, all six, quasi-static (" + second.generic_string() + "), axial");
}

// A stretch with calibrate's fitted k_link and glued beads says so: it is a different set-up from
// the default one beside it, not a copy to be told apart by directory.
TEST(ReportInputs, StretchLabelsNameAFittedLinkStiffnessAndRigidPatches) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto table2 = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 90, 0.3);
  auto fitted = table2;
  fitted.config_patch = {{"membrane", {{"k_link_kBT", 3.280659}}},
                         {"stretch", {{"contact", {{"rigid", true}}}}}};
  const auto page =
      parse_xml(build_report(read_run_directories({write_run(scratch.path() / "table2", table2),
                                                   write_run(scratch.path() / "fitted", fitted)}))
                    .html);
  std::vector<std::string> series;
  for (const auto i : page.find("g", "series"))
    series.push_back(page.elements[i].attribute("data-label"));
  ASSERT_EQ(series.size(), 6u);
  for (const std::string label : {"discocyte, all six, quasi-static, axial",
                                  "discocyte, all six, quasi-static, k_link 3.28 kBT, rigid "
                                  "patches, axial"}) {
    EXPECT_NE(std::find(series.begin(), series.end(), label), series.end()) << label;
  }
}

// The default k_link is the morphology's own: Table 2's 11 kBT is not news for a stomatocyte II,
// the discocyte's 7 is.
TEST(ReportInputs, StretchLabelsCompareTheLinkStiffnessWithTheMorphologysOwn) {
  rbcsim::testing::ScratchDirectory scratch;
  auto own = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 90, 0.3);
  own.morphology = "stomatocyte-II";
  own.config_patch = {{"membrane", {{"k_link_kBT", 11.0}}}};
  auto discocytes = own;
  discocytes.config_patch = {{"membrane", {{"k_link_kBT", 7.0}}}};
  const auto page = parse_xml(
      build_report(read_run_directories({write_run(scratch.path() / "own", own),
                                         write_run(scratch.path() / "disco", discocytes)}))
          .html);
  std::vector<std::string> series;
  for (const auto i : page.find("g", "series"))
    series.push_back(page.elements[i].attribute("data-label"));
  for (const std::string label : {"stomatocyte-II, all six, quasi-static, axial",
                                  "stomatocyte-II, all six, quasi-static, k_link 7 kBT, axial"}) {
    EXPECT_NE(std::find(series.begin(), series.end(), label), series.end()) << label;
  }
}

TEST(ReportInputs, TransitOrderDifferentFromThePaperIsSaid) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto documents = build_report(read_run_directories(
      {write_run(scratch.path() / "d", rbcsim::testing::capillary_run("discocyte", 2e-3, 1.4)),
       write_run(scratch.path() / "s",
                 rbcsim::testing::capillary_run("stomatocyte-II", 1e-3, 1.3))}));
  const auto& order = documents.summary.at("capillary").at("transit_time_order")[0];
  EXPECT_EQ(order.at("order"), (std::vector<std::string>{"stomatocyte-II", "discocyte"}));
  EXPECT_EQ(order.at("paper_order"), (std::vector<std::string>{"discocyte", "stomatocyte-II"}));
  EXPECT_FALSE(order.at("agrees_with_paper"));
  EXPECT_NE(documents.markdown.find("different order."), std::string::npos);
}

TEST(ReportInputs, MissingDirectoryIsNamed) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto missing = scratch.path() / "nowhere";
  EXPECT_EQ(report_error({missing}), missing.string() + ": no such directory");
  const auto file = scratch.path() / "plain.txt";
  write_file(file, "not a run");
  EXPECT_EQ(report_error({file}), file.string() + ": not a directory (expected a run directory)");
}

TEST(ReportInputs, MissingOrBrokenFilesAreNamed) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto run = write_run(scratch.path() / "run", rbcsim::testing::calibrate_run());
  std::filesystem::remove(run / "result.json");
  EXPECT_EQ(report_error({run}), (run / "result.json").string() + ": no such file");
  write_file(run / "result.json", "{\"command\": ");
  EXPECT_EQ(report_error({run}).rfind((run / "result.json").string() + ": line 1, column", 0), 0u)
      << report_error({run});
  std::filesystem::remove(run / "config.json");
  EXPECT_EQ(report_error({run}), (run / "config.json").string() + ": no such file");
}

TEST(ReportInputs, ContractViolationsNameTheJsonPath) {
  rbcsim::testing::ScratchDirectory scratch;
  auto stretch = rbcsim::testing::stretch_run(rbcsim::testing::all_terms(), 90, 0.3);
  stretch.section["points"][3].erase("axial_um");
  const auto run = write_run(scratch.path() / "stretch", stretch);
  EXPECT_EQ(report_error({run}),
            (run / "result.json").string() + ": /stretch/points/3: missing member \"axial_um\"");

  auto shear = rbcsim::testing::shear_run("discocyte", rbcsim::testing::all_terms(), 11);
  shear.section["rates"][1]["length_um"] = "long";
  const auto shear_run = write_run(scratch.path() / "shear", shear);
  EXPECT_EQ(report_error({shear_run}), (shear_run / "result.json").string() +
                                           ": /shear/rates/1/length_um: expected a number, found "
                                           "a string");

  auto bad_status = rbcsim::testing::calibrate_run();
  bad_status.status = "done";
  const auto status_run = write_run(scratch.path() / "status", bad_status);
  const auto threads_run = write_run(scratch.path() / "threads", rbcsim::testing::calibrate_run());
  auto result = nlohmann::json::parse(rbcsim::testing::read_text(threads_run / "result.json"));
  result["threads"] = 2.5;
  write_file(threads_run / "result.json", result.dump());
  EXPECT_EQ(report_error({threads_run}),
            (threads_run / "result.json").string() +
                ": /threads: expected an integer, found a number with a fraction or an exponent");

  EXPECT_EQ(report_error({status_run}),
            (status_run / "result.json").string() +
                ": /status: expected \"ok\", \"failed\" or \"interrupted\", found \"done\"");
}

TEST(ReportInputs, ConfigWithoutMembraneForcesIsNamed) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto run = write_run(scratch.path() / "run", rbcsim::testing::calibrate_run());
  write_file(run / "config.json", R"({"membrane": {"k_link_kBT": 7}})");
  EXPECT_EQ(report_error({run}),
            (run / "config.json").string() + ": /membrane: missing member \"forces\"");
}

// run.notices is optional (older run directories), but when present it is read like the rest.
TEST(ReportInputs, MalformedRunNoticesAreNamed) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto run = write_run(scratch.path() / "run", rbcsim::testing::calibrate_run());
  write_file(run / "config.json",
             R"({"membrane": {"forces": ["link"]}, "run": {"notices": ["fine", 3]}})");
  EXPECT_EQ(report_error({run}), (run / "config.json").string() +
                                     ": /run/notices/1: expected a string, found an integer");
  write_file(run / "config.json", R"({"membrane": {"forces": ["link"]}, "run": {}})");
  EXPECT_EQ(report_error({run}), "no error");
}

TEST(ReportInputs, BadCapillaryTimeSeriesIsNamed) {
  rbcsim::testing::ScratchDirectory scratch;
  auto capillary = rbcsim::testing::capillary_run("discocyte", 1e-3, 1.4);
  const auto run = write_run(scratch.path() / "capillary", capillary);
  const auto csv = run / "capillary_timeseries.csv";
  write_file(csv, "time_s,deformation_index\n0,1\n1e-4,abc\n");
  EXPECT_EQ(report_error({run}),
            csv.string() + ": line 3, column \"deformation_index\": \"abc\" is not a number");
  write_file(csv, "time_s,DI\n0,1\n");
  EXPECT_EQ(report_error({run}), csv.string() + ": no column \"deformation_index\"");
  std::filesystem::remove(csv);
  EXPECT_EQ(report_error({run}), csv.string() + ": no such file");
}

// The peak-DI comparison is the paper's Fig. 13 claim about F_ad and F_tc: a run without some
// other term is not compared with the six-term one.
TEST(ReportInputs, PeakDeformationIsComparedOnlyWithoutTheTwoNewTerms) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto six = rbcsim::testing::capillary_run("discocyte", 1e-3, 2.0);
  auto without_bend = rbcsim::testing::capillary_run("discocyte", 1e-3, 2.2);
  without_bend.forces = {"link", "area", "volume", "area_difference", "total_curvature"};
  const auto documents = build_report(
      read_run_directories({write_run(scratch.path() / "six", six),
                            write_run(scratch.path() / "without-bend", without_bend)}));
  EXPECT_EQ(documents.summary.at("capillary").at("peak_deformation_index_by_terms"),
            nlohmann::json::array());
  EXPECT_EQ(documents.markdown.find("Peak DI"), std::string::npos);
}

}  // namespace
