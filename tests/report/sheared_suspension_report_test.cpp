// The report's sheared-suspension section: runs of `shear --hematocrit` (result.json's
// "sheared_suspension" object, a time series per rate) against the wide-tube high-shear limit of
// Pries et al. (1992) at each rate's hematocrit; a stopped rate drawn in the strain plot only.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "report/reference_data.hpp"
#include "report/report.hpp"
#include "report/run_fixtures.hpp"
#include "support/scratch_directory.hpp"
#include "support/xml_document.hpp"

namespace {

using rbcsim::report::build_report;
using rbcsim::report::pries1992_large_tube_relative_viscosity;
using rbcsim::report::read_run_directories;
using rbcsim::testing::FixtureRun;
using rbcsim::testing::parse_xml;
using rbcsim::testing::write_run;

struct Rate {
  double shear_rate_per_s;
  double relative_viscosity;
  bool failed = false;
};

// A run of `shear --hematocrit` at one hematocrit: one entry and one time series per rate, the
// series settling on the rate's viscosity (the stresslet) with the near-wall measure 1 % above.
FixtureRun sheared_run(double hematocrit, const std::vector<Rate>& rates) {
  FixtureRun run{.command = "shear", .section_name = "sheared_suspension"};
  run.section = {{"boundary", "walls"},
                 {"morphologies", {"discocyte"}},
                 {"reference_diameter_um", 7.8},
                 {"rates", nlohmann::json::array()}};
  for (std::size_t i = 0; i < rates.size(); ++i) {
    const auto& rate = rates[i];
    const std::string directory = "rate_00" + std::to_string(i);
    nlohmann::json entry = {{"shear_rate_per_s", rate.shear_rate_per_s},
                            {"directory", directory},
                            {"simulated_shear_rate_per_s", 6.0 * rate.shear_rate_per_s},
                            {"cells", 12},
                            {"hematocrit", hematocrit},
                            {"relative_viscosity", rate.relative_viscosity},
                            {"relative_viscosity_sd", 0.02},
                            {"near_wall_relative_viscosity", 1.01 * rate.relative_viscosity},
                            {"averaged_samples", rate.failed ? 0 : 50},
                            {"strain", rate.failed ? 3.0 : 10.0},
                            {"samples_with_pierced_cells", 0}};
    if (rate.failed) entry["failure"] = "step 11227, cell 9: membrane term 'bend': at its limit";
    run.section["rates"].push_back(entry);
    std::string series =
        "time_s,strain,relative_viscosity,particle_stress_Pa,cytoplasm_stress_Pa,"
        "near_wall_relative_viscosity,contact_pairs,pierced_cells\n0,0,1,0,0,1,0,0\n";
    for (int sample = 1; sample <= (rate.failed ? 30 : 100); ++sample) {
      const double strain = 0.1 * sample;
      series += std::to_string(strain / rate.shear_rate_per_s) + "," + std::to_string(strain) +
                "," + std::to_string(rate.relative_viscosity) + ",0.1,0,";
      series += std::to_string(1.01 * rate.relative_viscosity) + ",3,0\n";
    }
    run.files[directory + "/suspension_timeseries.csv"] = series;
    if (rate.failed) run.status = "failed";
  }
  run.headline = {{"hematocrit", hematocrit}};
  return run;
}

// Whether a plot series of the page has this label.
bool has_series(const rbcsim::testing::XmlDocument& page, const std::string& label) {
  const auto labels = page.labels("series", -1);
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

// 5 % above the limit at 200 1/s, 40 % above it at 400, a third rate stopped: two comparisons
// the verdict tells apart, the stopped rate only in the strain plot.
TEST(ShearedSuspensionReport, FinishedRatesAgainstTheWideTubeLimit) {
  rbcsim::testing::ScratchDirectory scratch;
  const double limit = pries1992_large_tube_relative_viscosity(0.3);
  std::filesystem::create_directories(scratch.path() / "sheared" / "rate_000");
  std::filesystem::create_directories(scratch.path() / "sheared" / "rate_001");
  std::filesystem::create_directories(scratch.path() / "sheared" / "rate_002");
  const auto documents = build_report(read_run_directories({write_run(
      scratch.path() / "sheared",
      sheared_run(0.3, {{200.0, 1.05 * limit}, {400.0, 1.4 * limit}, {800.0, 2.0, true}}))}));
  const auto& section = documents.summary.at("sheared_suspension");
  const auto& comparisons = section.at("comparisons");
  ASSERT_EQ(comparisons.size(), 2u);
  EXPECT_EQ(comparisons[0].at("verdict"), "within 15 %");
  EXPECT_EQ(comparisons[0].at("difference"), "5 %");
  EXPECT_EQ(comparisons[1].at("verdict"), "differs by more than 15 %");
  EXPECT_EQ(comparisons[1].at("comparison"),
            "sheared suspension H 0.3, discocyte, 12 cells, 400 1/s: relative viscosity");
  // The verdict section carries them too.
  const auto& verdict = documents.summary.at("verdict");
  EXPECT_EQ(std::count_if(
                verdict.begin(), verdict.end(),
                [](const nlohmann::json& row) {
                  return row.at("comparison").get<std::string>().rfind("sheared suspension", 0) ==
                         0;
                }),
            2);
  const auto page = parse_xml(documents.html);
  ASSERT_EQ(page.error, "");
  const std::string run = "H 0.3, discocyte, 12 cells";
  EXPECT_TRUE(has_series(page, run + " (failed)"));  // the plot against the rate
  EXPECT_TRUE(has_series(page, run + ", 200 1/s"));
  EXPECT_TRUE(has_series(page, run + ", 800 1/s (stopped)"));
  EXPECT_TRUE(has_series(page, run + ", 800 1/s (stopped): near the walls"));
  EXPECT_TRUE(has_series(page, "Pries et al. 1992, wide-tube limit, H 0.3"));
  // The plot against the rate has the two finished rates only.
  const auto labels = page.labels("series", -1);
  const auto against_rate = std::find(labels.begin(), labels.end(), run + " (failed)");
  ASSERT_NE(against_rate, labels.end());
  const auto series =
      page.find("g", "series")[static_cast<std::size_t>(against_rate - labels.begin())];
  EXPECT_EQ(page.find("circle", "marker", static_cast<long>(series)).size(), 2u);
}

TEST(ShearedSuspensionReport, PiercedCellsWithholdTheVerdict) {
  rbcsim::testing::ScratchDirectory scratch;
  auto run = sheared_run(0.2, {{200.0, 2.0}});
  run.section["rates"][0]["samples_with_pierced_cells"] = 4;
  std::filesystem::create_directories(scratch.path() / "pierced" / "rate_000");
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "pierced", run)}));
  const auto& comparisons = documents.summary.at("sheared_suspension").at("comparisons");
  ASSERT_EQ(comparisons.size(), 1u);
  EXPECT_EQ(comparisons[0].at("verdict"), "not a result: cells pierced each other in 4 samples");
}

// Runs written before the rates named their directories: the table and the plot against the rate
// without the strain plot's series; one-cell shear runs stay in the shear section.
TEST(ShearedSuspensionReport, OlderRunsWithoutRateDirectories) {
  rbcsim::testing::ScratchDirectory scratch;
  auto run = sheared_run(0.2, {{200.0, 2.0}});
  run.section["rates"][0].erase("directory");
  const auto documents =
      build_report(read_run_directories({write_run(scratch.path() / "older", run)}));
  EXPECT_EQ(documents.summary.at("sheared_suspension").at("comparisons").size(), 1u);
  EXPECT_FALSE(documents.summary.contains("shear"));
  const auto page = parse_xml(documents.html);
  EXPECT_FALSE(has_series(page, "H 0.2, discocyte, 12 cells, 200 1/s"));
}

}  // namespace
