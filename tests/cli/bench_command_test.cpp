// `rbcsim bench`: one run prints every figure the design asks for, as text and as JSON. It takes
// tens of seconds (it measures), hence a Validate suite: label `validate`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace {

using rbcsim::testing::run_rbcsim;

TEST(ValidateBenchCommand, JsonHasBandwidthFluidAndCoupledFiguresPerThreadCount) {
  const rbcsim::testing::ScratchDirectory scratch;
  const auto result =
      run_rbcsim("bench --json --threads 2 --large-lattice 64 64 32 --cells 3 1 --output '" +
                     scratch.path().string() + "'",
                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto report = nlohmann::json::parse(result.out);
  EXPECT_FALSE(report["machine"]["cpu_model"].get<std::string>().empty());
  EXPECT_EQ(report["machine"]["omp_wait_policy"], "passive");  // ctest's environment
  ASSERT_EQ(report["runs"].size(), 2u);
  EXPECT_EQ(report["runs"][0]["threads"], 1);
  EXPECT_EQ(report["runs"][1]["threads"], 2);
  for (const auto& run : report["runs"]) {
    EXPECT_GT(run["memory_bandwidth_GB_per_s"].get<double>(), 0.0);
    // The roofline is the bandwidth over 304 bytes per node update.
    EXPECT_NEAR(run["roofline_mlups"].get<double>(),
                run["memory_bandwidth_GB_per_s"].get<double>() * 1e3 / 304.0,
                1e-9 * run["roofline_mlups"].get<double>());
    ASSERT_EQ(run["fluid"].size(), 2u);
    EXPECT_EQ(run["fluid"][0]["lattice"], (nlohmann::json{40, 40, 20}));
    EXPECT_EQ(run["fluid"][1]["lattice"], (nlohmann::json{64, 64, 32}));
    for (const auto& fluid : run["fluid"]) {
      EXPECT_GT(fluid["optimised_mlups"].get<double>(), 0.0);
      EXPECT_GT(fluid["reference_mlups"].get<double>(), 0.0);
      EXPECT_GT(fluid["single_mlups"].get<double>(), 0.0);
      // Single precision's roofline is twice double's (152 against 304 bytes per node update).
      EXPECT_NEAR(fluid["single_roofline_fraction"].get<double>(),
                  fluid["single_mlups"].get<double>() / (2.0 * run["roofline_mlups"].get<double>()),
                  1e-12);
    }
    ASSERT_EQ(run["coupled"].size(), 2u);
    EXPECT_EQ(run["coupled"][0]["vertices"], 642);
    EXPECT_EQ(run["coupled"][1]["vertices"], 2562);
    EXPECT_GT(run["coupled"][0]["ms_per_step"].get<double>(), 0.0);
    // The shipped reference has HemoCell's one-core step only, for the 642-vertex cell.
    EXPECT_EQ(run["coupled"][0]["speedup_vs_reference"].is_null(), run["threads"] != 1);
    EXPECT_TRUE(run["coupled"][1]["speedup_vs_reference"].is_null());
    EXPECT_TRUE(run["fluid"][0]["speedup_vs_reference"].is_null());
    // The suspensions, fewest cells first, each cell with its own block of a row along x.
    const auto& suspension = run["suspension"];
    ASSERT_EQ(suspension.size(), 2u);
    EXPECT_EQ(suspension[0]["cells"], 1);
    EXPECT_EQ(suspension[1]["cells"], 3);
    EXPECT_EQ(suspension[1]["vertices"], 3 * 642);
    EXPECT_EQ(suspension[1]["lattice"][0].get<int>(), 3 * suspension[0]["lattice"][0].get<int>());
    EXPECT_EQ(suspension[0]["contact_pairs"], 0);  // one cell has no one to touch
    EXPECT_GT(suspension[1]["contact_pairs"].get<int>(), 0);
    EXPECT_EQ(suspension[0]["per_cell_over_fewest_cells"], 1.0);
    for (const auto& entry : suspension) {
      EXPECT_NEAR(entry["ms_per_step_per_cell"].get<double>(),
                  entry["ms_per_step"].get<double>() / entry["cells"].get<double>(), 1e-12);
      double shares = 0.0;
      for (const auto& [name, share] : entry["shares"].items()) {
        EXPECT_GE(share.get<double>(), -1e-12) << name;
        shares += share.get<double>();
      }
      EXPECT_NEAR(shares, 1.0, 1e-9);
    }
    EXPECT_GT(suspension[1]["shares"]["contact"].get<double>(), 0.0);
  }
  EXPECT_EQ(report["reference"]["label"], "HemoCell d916987 + Palabos 2.3.0");
  EXPECT_EQ(nlohmann::json::parse(rbcsim::testing::read_text(scratch.path() / "bench.json")),
            report);
}

}  // namespace
