// `rbcsim shear` end to end: the built binary on a coarse cell (642 vertices on a 1 um lattice,
// one unit of strain per rate, a second or two), the run directory it writes, exit codes and
// diagnostics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
using rbcsim::testing::result_schema_problems;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

constexpr const char* kCoarseRun =
    "shear --set mesh.subdivisions=3 --set mesh.method=parametric --set lattice.spacing_um=1 "
    "--set shear.max_reynolds_number=0.4 --set shear.width_diameters=1.6 "
    "--set shear.gap_diameters=2 --max-strain 1 ";

TEST(CliShear, WritesTheRunDirectoryAndPrintsItsResultAsJson) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string(kCoarseRun) + "--rates 0,500 --threads 2 --json " +
                                     "--output '" + run_dir.string() + "'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // stderr is not a terminal, so no progress; only the notice that this cell's edges (0.49 um)
  // are half a lattice spacing (setup::add_edge_spacing_notice), which config.json keeps too.
  const auto notices = read_json(run_dir / "config.json")["run"]["notices"];
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(result.err, "rbcsim: notice: " + notices[0].get<std::string>() + "\n");
  EXPECT_NE(result.err.find("0.49 lattice spacings (lattice.spacing_um = 1)"), std::string::npos);
  const auto printed = printed_run_result(result, run_dir, "shear");
  EXPECT_EQ(printed["threads"], 2);
  const auto& shear = printed["shear"];
  EXPECT_EQ(shear["boundary"], "lees-edwards");
  ASSERT_EQ(shear["rates"].size(), 2u);
  EXPECT_EQ(shear["rates"][1]["shear_rate_per_s"], 500.0);
  EXPECT_GT(shear["rates"][1]["viscosity_scale"].get<double>(), 1.0);
  EXPECT_GT(shear["rates"][1]["length_um"].get<double>(),
            shear["rates"][0]["length_um"].get<double>());

  const auto config = read_json(run_dir / "config.json");
  EXPECT_EQ(config["run"]["command"], "shear");
  EXPECT_EQ(config["run"]["mesh_source"], "built-in discocyte level 3");
  EXPECT_EQ(config["shear"]["rates_per_s"], "0,500");
  EXPECT_EQ(config["shear"]["max_strain"], 1.0);

  const auto table = rbcsim::io::read_csv_file(run_dir / "shear.csv");
  EXPECT_EQ(table.numbers("shear_rate_per_s"), (std::vector<double>{0, 500}));
  EXPECT_EQ(table.numbers("length_um")[1], shear["rates"][1]["length_um"].get<double>());
  EXPECT_EQ(table.numbers("max_triangle_area_deviation")[1],
            shear["rates"][1]["max_triangle_area_deviation"].get<double>());
  EXPECT_TRUE(fs::exists(run_dir / "shapes/shear_000.vtp"));
  EXPECT_TRUE(fs::exists(run_dir / "shapes/shear_001.vtp"));
  // Four samples per unit strain; the last within a sample interval of the end, where the shape is
  // the final one (no half turn yet, so no window: shear_case_test.cpp).
  const auto history = rbcsim::io::read_csv_file(run_dir / "rate_001/history.csv");
  ASSERT_EQ(history.numbers("strain").size(), 4u);
  EXPECT_EQ(shear["rates"][1]["window_strain"], 0.0);
  EXPECT_NEAR(history.numbers("length_um").back(), shear["rates"][1]["length_um"].get<double>(),
              0.01);
  const auto collection = read_text(run_dir / "shear.pvd");
  EXPECT_NE(collection.find("timestep=\"500\""), std::string::npos) << collection;
}

TEST(CliShear, TextTablePrintsReynoldsAndCapillaryNumbers) {
  const ScratchDirectory scratch;
  const auto result = run_rbcsim(std::string(kCoarseRun) + "--rates 1000 --threads 1 --output '" +
                                     (scratch.path() / "run").string() + "'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("rate_1/s   sim_rate       Re       Ca"), std::string::npos)
      << result.out;
}

TEST(CliShear, BadInputExitsTwoWithOneLineAndNoRunDirectory) {
  const ScratchDirectory scratch;
  const auto out = (scratch.path() / "run").string();
  const auto negative = run_rbcsim("shear --rates=-5 --output '" + out + "'", scratch.path());
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_EQ(negative.err,
            "rbcsim: error: --rates: shear rates must be >= 0 1/s (the flow direction is fixed)\n");
  const auto boundary = run_rbcsim("shear --boundary slip --output '" + out + "'", scratch.path());
  EXPECT_EQ(boundary.exit_code, 2);
  EXPECT_NE(boundary.err.find("shear.boundary"), std::string::npos) << boundary.err;
  const auto mach =
      run_rbcsim("shear --rates 1e7 --set shear.viscosity_scaling=false --output '" + out + "'",
                 scratch.path());
  EXPECT_EQ(mach.exit_code, 2);
  EXPECT_NE(mach.err.find("shear rate 1e+07 1/s"), std::string::npos) << mach.err;
  EXPECT_FALSE(fs::exists(out));
}

// The physiological membrane's viscosity is an implicit step on the fluid (docs/physics.md): the
// reference fluid kernel solves it every lattice step, the optimised one every second step (its
// populations are in natural order only then). Both must carry a sheared discocyte (162 vertices
// on dx 1 um, 1000 1/s) to strain 2.5. Before the step took the fluid's half force into its
// velocity, the reference kernel's run lost volume until the volume term's limit stopped it at
// strain 2.0. The two intervals are a first-order splitting of the same step: at strain 3 they
// gave DI 0.463 / 0.463, inclination -45.7 / -47.4 deg, tank-treading 55.9 / 57.9 Hz (642
// vertices on dx 0.75 um: 0.472 / 0.461, -46.5 / -47.8, 55.8 / 57.6), so the bounds below allow
// about twice the larger difference.
TEST(CliShear, ThePhysiologicalMembraneRunsWhicheverKernelSolvesItsViscosity) {
  const ScratchDirectory scratch;
  nlohmann::json rates[2];
  int k = 0;
  for (const char* kernel : {"reference", "optimised"}) {
    const auto run_dir = scratch.path() / kernel;
    const auto result = run_rbcsim(
        std::string("shear --preset physiological --rates 1000 --max-strain 2.5 ") +
            "--set mesh.subdivisions=2 --set lattice.spacing_um=1 --set lattice.kernel=" + kernel +
            " --output '" + run_dir.string() + "'",
        scratch.path());
    ASSERT_EQ(result.exit_code, 0) << kernel << ": " << result.err;
    rates[k++] = read_json(run_dir / "result.json")["shear"]["rates"][0];
  }
  EXPECT_NEAR(rates[0]["deformation_index"].get<double>(),
              rates[1]["deformation_index"].get<double>(), 0.025);
  EXPECT_NEAR(rates[0]["inclination_deg"].get<double>(), rates[1]["inclination_deg"].get<double>(),
              3.5);
  EXPECT_NEAR(
      rates[0]["tank_treading_hz"].get<double>() / rates[1]["tank_treading_hz"].get<double>(), 1.0,
      0.08);
}

// An instability (here: any vertex motion counts as too fast): exit 1, the run directory still
// written with status "failed", the rate's failure dump kept.
TEST(CliShear, InstabilityExitsOneAndRecordsTheFailure) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(
      std::string(kCoarseRun) + "--rates 2000 --set stability.max_vertex_step_dx=1e-12 --output '" +
          run_dir.string() + "'",
      scratch.path());
  EXPECT_EQ(result.exit_code, 1);
  // After the edge-to-spacing notice of this coarse cell (see the test above).
  EXPECT_NE(result.err.find("\nrbcsim: failed: shear: rate 2000 1/s: step 1"), std::string::npos)
      << result.err;
  const auto written = read_json(run_dir / "result.json");
  EXPECT_EQ(written["status"], "failed");
  EXPECT_EQ(written["shear"]["rates"][0]["steady"], false);
  EXPECT_TRUE(fs::exists(run_dir / "rate_000/failure/failure.json"));
  EXPECT_EQ(result_schema_problems(written), std::vector<std::string>{});
}

// A rate that fails is not the sweep's headline: the highest rate that finished is. Here the
// local-area limit is lowered to 0.02, which the cell at rest never nears (d ~ 1e-15) and the
// cell at 2000 1/s crosses within a few dozen steps.
TEST(CliShear, HeadlineIsTheHighestRateThatFinished) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string(kCoarseRun) +
                                     "--rates 0,2000 --set membrane.tau_area=0.02 --output '" +
                                     run_dir.string() + "'",
                                 scratch.path());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("rate 2000 1/s: step "), std::string::npos) << result.err;
  const auto written = read_json(run_dir / "result.json");
  EXPECT_EQ(written["status"], "failed");
  const auto& rates = written["shear"]["rates"];
  ASSERT_EQ(rates.size(), 2u);
  EXPECT_FALSE(rates[0].contains("failure"));
  EXPECT_TRUE(rates[1].contains("failure"));
  const auto& headline = written["headline"];
  EXPECT_EQ(headline["max_shear_rate_per_s"], 0.0);
  EXPECT_EQ(headline["length_um_at_max_rate"], rates[0]["length_um"]);
  EXPECT_EQ(headline["failed_rate_count"], 1);
  // One strain is too short for rate 0 to be steady: unsteady, but not failed.
  EXPECT_EQ(rates[0]["steady"], false);
  EXPECT_EQ(headline["unsteady_rate_count"], 1);
}

}  // namespace

namespace {

constexpr const char* kCoarseSuspension =
    "shear --set mesh.subdivisions=2 --set mesh.method=parametric "
    "--set lattice.spacing_um=1 --set suspension.contact_range_um=1.75 ";

// --hematocrit: cells packed between sliding walls, one run per rate, their relative viscosity.
TEST(CliShear, ASuspensionBetweenWallsWritesItsViscosityPerRate) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result =
      run_rbcsim(std::string(kCoarseSuspension) +
                     "--hematocrit 0.1 --rates 200 --set suspension.strain=1 --threads 1 --json "
                     "--output '" +
                     run_dir.string() + "'",
                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // The contact acts within the kernel's 2 um at dx 1 um: the notice says so.
  EXPECT_NE(result.err.find("suspension.contact_range_um 1.75 um"), std::string::npos)
      << result.err;
  const auto printed = printed_run_result(result, run_dir, "shear");
  const auto& section = printed["sheared_suspension"];
  EXPECT_EQ(section["boundary"], "walls");
  ASSERT_EQ(section["rates"].size(), 1u);
  const auto& rate = section["rates"][0];
  EXPECT_EQ(rate["shear_rate_per_s"], 200.0);
  EXPECT_GT(rate["cells"].get<int>(), 3);
  EXPECT_NEAR(rate["hematocrit"].get<double>(), 0.1, 0.02);  // whole cells
  EXPECT_GT(rate["relative_viscosity"].get<double>(), 1.0);
  const double h = rate["hematocrit"].get<double>();  // Pries' wide-tube limit, by hand
  EXPECT_NEAR(rate["pries1992_large_tube_relative_viscosity"].get<double>(),
              1.0 + 2.2 * (std::pow(1.0 - h, -0.8) - 1.0) / (std::pow(0.55, -0.8) - 1.0), 1e-12);
  EXPECT_EQ(rate["samples_with_pierced_cells"], 0);
  EXPECT_NEAR(rate["strain"].get<double>(), 1.0, 0.01);
  EXPECT_EQ(printed["headline"]["relative_viscosity"], rate["relative_viscosity"]);
  const auto config = read_json(run_dir / "config.json");
  EXPECT_EQ(config["shear"]["boundary"], "walls");  // implied by --hematocrit
  const auto table = rbcsim::io::read_csv_file(run_dir / "sheared_suspension.csv");
  EXPECT_EQ(table.numbers("shear_rate_per_s"), (std::vector<double>{200}));
  const auto samples = rbcsim::io::read_csv_file(run_dir / "rate_000/suspension_timeseries.csv");
  EXPECT_EQ(samples.numbers("strain").size(), 11u);  // every 0.1 of strain, from 0
  EXPECT_TRUE(fs::exists(run_dir / "rate_000/cells_timeseries.csv"));
  EXPECT_TRUE(fs::exists(run_dir / "rate_000/cells.pvd"));
}

// --checkpoint-every leaves each rate's last checkpoint in rate_<i>/ and a finished rate's
// point.json; --resume keeps a finished rate (its snapshots, removed here, are not written
// again) and runs an unfinished one on from its checkpoint: the same results as the straight run.
TEST(CliShear, ResumeOfASuspensionSweepKeepsFinishedRatesAndResumesTheRest) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const std::string settings = std::string(kCoarseSuspension) +
                               "--hematocrit 0.1 --rates 200,400 --set suspension.strain=0.5 "
                               "--threads 1 --quiet ";
  const auto straight = run_rbcsim(
      settings + "--checkpoint-every 20 --output '" + run_dir.string() + "'", scratch.path());
  ASSERT_EQ(straight.exit_code, 0) << straight.err;
  const auto straight_result = read_json(run_dir / "result.json");
  ASSERT_GT(straight_result["sheared_suspension"]["rates"][1]["steps"].get<double>(), 20.0);
  const auto second_samples = read_text(run_dir / "rate_001/suspension_timeseries.csv");
  const auto second_cells = read_text(run_dir / "rate_001/cells_timeseries.csv");
  ASSERT_TRUE(fs::exists(run_dir / "rate_000/point.json"));
  ASSERT_TRUE(fs::exists(run_dir / "rate_001/checkpoint.bin"));
  // The first rate finished; the second as if stopped after its last checkpoint.
  fs::remove(run_dir / "rate_000/cells.pvd");
  fs::remove(run_dir / "rate_001/point.json");
  for (const char* name : {"result.json", "sheared_suspension.csv",
                           "rate_001/suspension_timeseries.csv", "rate_001/cells_timeseries.csv"}) {
    fs::remove(run_dir / name);
  }

  const auto resumed = run_rbcsim(settings + "--resume '" + run_dir.string() + "'", scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto resumed_result = read_json(run_dir / "result.json");
  EXPECT_EQ(resumed_result["sheared_suspension"], straight_result["sheared_suspension"]);
  EXPECT_EQ(resumed_result["headline"], straight_result["headline"]);
  EXPECT_EQ(read_text(run_dir / "rate_001/suspension_timeseries.csv"), second_samples);
  EXPECT_EQ(read_text(run_dir / "rate_001/cells_timeseries.csv"), second_cells);
  EXPECT_FALSE(fs::exists(run_dir / "rate_000/cells.pvd"));  // not run again
  EXPECT_TRUE(fs::exists(run_dir / "rate_001/point.json"));

  // Another config is refused, naming the option that differs from the run's config.json; and
  // without config.json, a finished rate's record of another config is refused, naming it.
  const std::string other_settings =
      settings + "--set suspension.sample_interval_strain=0.25 --resume '" + run_dir.string() + "'";
  const auto other = run_rbcsim(other_settings, scratch.path());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("config.json"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("suspension.sample_interval_strain"), std::string::npos) << other.err;
  fs::remove(run_dir / "config.json");
  const auto other_record = run_rbcsim(other_settings, scratch.path());
  EXPECT_EQ(other_record.exit_code, 2);
  EXPECT_NE(other_record.err.find("rate_000/point.json"), std::string::npos) << other_record.err;
}

TEST(CliShear, ABadSuspensionExitsTwoWithOneLineAndNoRunDirectory) {
  const ScratchDirectory scratch;
  const auto out = (scratch.path() / "run").string();
  const auto expect_refused = [&](const std::string& arguments, const std::string& key) {
    const auto result = run_rbcsim(
        std::string(kCoarseSuspension) + arguments + " --output '" + out + "'", scratch.path());
    EXPECT_EQ(result.exit_code, 2) << arguments;
    EXPECT_EQ(result.err.rfind("rbcsim: error: " + key + ": ", 0), 0u) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  };
  expect_refused("--hematocrit 0.1 --boundary lees-edwards", "shear.boundary");
  expect_refused("--hematocrit 0.1 --rates 0,200", "shear.rates_per_s");
  // Cannot be packed: refused after any number of iterations (20 take 2 s under the sanitizers).
  expect_refused("--hematocrit 0.69 --rates 200 --set suspension.packing_max_iterations=20",
                 "suspension.hematocrit");
}

}  // namespace
