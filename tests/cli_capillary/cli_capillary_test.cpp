// `rbcsim capillary` end to end: the built binary on a coarse set-up (162-vertex discocyte,
// dx = 1 um, a fast inflow), the run directory it writes against the run-directory contract and
// schemas/result.schema.json, exit codes and diagnostics.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/csv_table.hpp"
#include "support/run_rbcsim.hpp"
#include "support/run_result.hpp"
#include "support/scratch_directory.hpp"

namespace {

namespace fs = std::filesystem;
using rbcsim::testing::printed_run_result;
using rbcsim::testing::read_json;
using rbcsim::testing::read_text;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

// tests/cases/capillary_case_test.cpp explains these: a stiffened 162-vertex cell at Ca ~ 0.5.
constexpr const char* kCoarse =
    "--set mesh.subdivisions=2 --set mesh.method=parametric --set lattice.spacing_um=1 --set "
    "membrane.k_link_kBT=112 "
    "--set membrane.k_area_kBT=80 --set membrane.k_bend_kBT=800 --set membrane.k_volume_kBT=320 "
    "--set membrane.k_area_difference_kBT=4800 --set membrane.k_total_curvature_kBT=1600 "
    "--set membrane.vertex_force_cap_pN=2000 --set capillary.throat_diameter_um=9 "
    "--set capillary.inlet_velocity_m_per_s=0.014 --set capillary.pass_margin_um=2 "
    "--set output.membrane_interval_s=2e-4 --set output.fluid_interval_s=1e-3 ";

TEST(CliCapillary, WritesTheRunDirectoryAndPrintsItsResultAsJson) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string("capillary ") + kCoarse +
                                     "--threads 1 --json --output '" + run_dir.string() + "'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");  // stderr is not a terminal: no progress
  const auto printed = printed_run_result(result, run_dir, "capillary");
  const auto& capillary = printed["capillary"];
  EXPECT_EQ(capillary["geometry"], "paper-validation");
  EXPECT_EQ(capillary["passed"], true);
  EXPECT_GT(capillary["transit_time_s"].get<double>(), 0.0);
  EXPECT_EQ(printed["headline"]["reynolds_number"], capillary["reynolds_number"]);
  // Where the steps' time went: every coupled step timed, the fluid and the membrane took some.
  const auto& phases = printed["phase_ms_per_step"];
  EXPECT_EQ(phases["timed_steps"], capillary["steps"]);
  EXPECT_GT(phases["fluid"].get<double>(), 0.0);
  EXPECT_GT(phases["membrane"].get<double>(), 0.0);

  const auto config = read_json(run_dir / "config.json");
  EXPECT_EQ(config["run"]["command"], "capillary");
  EXPECT_EQ(config["capillary"]["inlet_velocity_m_per_s"], 0.014);

  const auto table = rbcsim::io::read_csv_file(run_dir / "capillary_timeseries.csv");
  const auto time_s = table.numbers("time_s");
  ASSERT_GE(time_s.size(), 3u);
  EXPECT_EQ(time_s.front(), 0.0);
  EXPECT_EQ(table.numbers("deformation_index").size(), time_s.size());
  EXPECT_EQ(table.numbers("centroid_z_um").size(), time_s.size());
  EXPECT_EQ(table.numbers("velocity_x_m_per_s").front(), 0.0);  // released at rest
  // The area strain: none at release (to the round-off of placing the cell in lattice units and
  // back); the result's extremes are the table's (both written to 17 digits).
  const auto area_change = table.numbers("area_change");
  const auto triangle_deviation = table.numbers("max_triangle_area_deviation");
  EXPECT_NEAR(area_change.front(), 0.0, 1e-13);
  EXPECT_NEAR(triangle_deviation.front(), 0.0, 1e-13);
  EXPECT_EQ(capillary["min_area_change"].get<double>(),
            *std::min_element(area_change.begin(), area_change.end()));
  EXPECT_EQ(capillary["max_area_change"].get<double>(),
            *std::max_element(area_change.begin(), area_change.end()));
  const double largest_deviation =
      *std::max_element(triangle_deviation.begin(), triangle_deviation.end());
  EXPECT_EQ(capillary["max_triangle_area_deviation"].get<double>(), largest_deviation);
  EXPECT_GT(largest_deviation, 0.0);
  EXPECT_LT(largest_deviation, 0.3);  // below membrane.tau_area, or the run would have failed
  for (const auto* file : {"cell0.pvd", "fluid.pvd"}) {
    EXPECT_NE(read_text(run_dir / file).find("<DataSet"), std::string::npos) << file;
  }
}

TEST(CliCapillary, BadInputExitsTwoWithOneLineAndNoRunDirectory) {
  const ScratchDirectory scratch;
  const auto out = (scratch.path() / "run").string();
  const auto geometry =
      run_rbcsim("capillary --geometry tube --output '" + out + "'", scratch.path());
  EXPECT_EQ(geometry.exit_code, 2);
  EXPECT_NE(geometry.err.find("--hematocrit"), std::string::npos) << geometry.err;
  const auto wall =
      run_rbcsim("capillary --wall missing.stl --output '" + out + "'", scratch.path());
  EXPECT_EQ(wall.exit_code, 2);
  EXPECT_NE(wall.err.find("missing.stl"), std::string::npos) << wall.err;
  const auto wide = run_rbcsim(std::string("capillary ") + kCoarse +
                                   "--set mesh.discocyte.radius_um=5.5 --output '" + out + "'",
                               scratch.path());
  EXPECT_EQ(wide.exit_code, 2);
  EXPECT_EQ(std::count(wide.err.begin(), wide.err.end(), '\n'), 1) << wide.err;
  EXPECT_FALSE(fs::exists(out));
}

// A cell that has not passed when the time runs out: exit 1, status failed with the reason, the
// run directory still written, and the text summary with the flow's Reynolds and capillary
// numbers.
TEST(CliCapillary, NotPassingInTimeExitsOneAndRecordsIt) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result =
      run_rbcsim(std::string("capillary ") + kCoarse + "--geometry paper-morphology " +
                     "--set capillary.max_time_s=5e-5 --output '" + run_dir.string() + "'",
                 scratch.path());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("did not pass the narrow section"), std::string::npos) << result.err;
  for (const auto* text :
       {"capillary (paper-morphology), discocyte, terms: link bend area volume area_difference "
        "total_curvature\n",
        " Re 0.1", " Ca 0.5", "NOT PASSED"}) {
    EXPECT_NE(result.out.find(text), std::string::npos) << text << " in " << result.out;
  }
  const auto written = read_json(run_dir / "result.json");
  EXPECT_EQ(written["status"], "failed");
  EXPECT_EQ(written["capillary"]["passed"], false);
  EXPECT_TRUE(written["capillary"]["transit_time_s"].is_null());
}

}  // namespace
