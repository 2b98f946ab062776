// `rbcsim stretch` end to end: the built binary on a coarse cell (level 2, 162 vertices, so a run
// takes a fraction of a second), the run directory it writes, exit codes and diagnostics.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

constexpr const char* kCoarseCell = "--set mesh.subdivisions=2 --set mesh.method=parametric ";

// A long run logged to a file asks for progress with --verbose: whole lines on stderr (the first
// at once, then at most one per 30 s), never on stdout.
TEST(CliStretch, VerboseLogsProgressLinesWhenStderrIsNotATerminal) {
  const ScratchDirectory scratch;
  const std::string run = std::string("stretch ") + kCoarseCell + "--forces 0,5 --threads 1 ";
  const auto verbose =
      run_rbcsim(run + "--verbose --json --output '" + (scratch.path() / "verbose").string() + "'",
                 scratch.path());
  ASSERT_EQ(verbose.exit_code, 0) << verbose.err;
  EXPECT_EQ(verbose.err.rfind("stretch: 1/2 forces, F = 0 pN, ", 0), 0u) << verbose.err;
  EXPECT_EQ(verbose.err.find('\r'), std::string::npos);
  EXPECT_EQ(verbose.err.back(), '\n');
  EXPECT_TRUE(nlohmann::json::accept(verbose.out)) << verbose.out;
  const auto plain = run_rbcsim(
      run + "--json --output '" + (scratch.path() / "plain").string() + "'", scratch.path());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.err, "");
}

TEST(CliStretch, WritesTheRunDirectoryAndPrintsItsResultAsJson) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result =
      run_rbcsim(std::string("stretch ") + kCoarseCell +
                     "--forces 0:10:5 --threads 1 --json --output '" + run_dir.string() + "'",
                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");  // stderr is not a terminal: no progress
  const auto printed = printed_run_result(result, run_dir, "stretch");
  EXPECT_EQ(printed["threads"], 1);
  const auto& stretch = printed["stretch"];
  EXPECT_EQ(stretch["mode"], "quasi-static");
  EXPECT_EQ(stretch["forces_terms"].size(), 6u);
  ASSERT_EQ(stretch["points"].size(), 3u);
  EXPECT_GT(stretch["points"][2]["axial_um"].get<double>(),
            stretch["points"][0]["axial_um"].get<double>());
  EXPECT_EQ(stretch["comparison"]["point_count"], 1);  // Mills' 0 pN; 16 pN is beyond 10 pN

  const auto config = read_json(run_dir / "config.json");
  EXPECT_EQ(config["run"]["command"], "stretch");
  EXPECT_EQ(config["run"]["mesh_source"], "built-in discocyte level 2");
  EXPECT_EQ(config["run"]["mesh_sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(config["stretch"]["forces_pN"], "0:10:5");
  EXPECT_TRUE(config.contains("derived"));

  const auto table = rbcsim::io::read_csv_file(run_dir / "stretch.csv");
  EXPECT_EQ(table.numbers("force_pN"), (std::vector<double>{0, 5, 10}));
  EXPECT_EQ(table.numbers("axial_um")[1], stretch["points"][1]["axial_um"].get<double>());
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(fs::exists(run_dir / ("shapes/stretch_00" + std::to_string(i) + ".vtp")));
  }
  const auto collection = read_text(run_dir / "stretch.pvd");
  EXPECT_NE(collection.find("timestep=\"10\""), std::string::npos) << collection;
}

// The text table by default, nothing with --quiet; an imported mesh file gets the checksum of
// its mesh, the same on every run.
TEST(CliStretch, TextTableAndMeshChecksumOfAnImportedFile) {
  const ScratchDirectory scratch;
  ASSERT_EQ(run_rbcsim("mesh generate --method parametric --subdivisions 2 -o '" +
                           (scratch.path() / "cell.stl").string() + "'",
                       scratch.path())
                .exit_code,
            0);
  const auto generated =
      run_rbcsim(std::string("stretch ") + kCoarseCell + "--forces 0 --output '" +
                     (scratch.path() / "a").string() + "'",
                 scratch.path());
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  EXPECT_NE(generated.out.find("force_pN   axial_um   transverse_um"), std::string::npos)
      << generated.out;
  const auto imported =
      run_rbcsim("stretch --set mesh.file='" + (scratch.path() / "cell.stl").string() +
                     "' --forces 0 --quiet --output '" + (scratch.path() / "b").string() + "'",
                 scratch.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_EQ(imported.out, "");  // --quiet
  const auto again =
      run_rbcsim("stretch --set mesh.file='" + (scratch.path() / "cell.stl").string() +
                     "' --forces 0 --quiet --output '" + (scratch.path() / "c").string() + "'",
                 scratch.path());
  EXPECT_EQ(read_json(scratch.path() / "b/config.json")["run"]["mesh_sha256"],
            read_json(scratch.path() / "c/config.json")["run"]["mesh_sha256"]);
}

TEST(CliStretch, BadInputExitsTwoWithOneLineAndNoRunDirectory) {
  const ScratchDirectory scratch;
  const auto out = (scratch.path() / "run").string();
  const auto bad_range =
      run_rbcsim("stretch --forces 0:abc --output '" + out + "'", scratch.path());
  EXPECT_EQ(bad_range.exit_code, 2);
  EXPECT_EQ(bad_range.err, "rbcsim: error: --forces: range \"0:abc\": \"abc\" is not a number\n");
  const auto negative = run_rbcsim("stretch --forces=-5 --output '" + out + "'", scratch.path());
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_EQ(negative.err, "rbcsim: error: --forces: forces must be >= 0 pN (the tweezers pull)\n");
  const auto mode = run_rbcsim("stretch --mode molten --output '" + out + "'", scratch.path());
  EXPECT_EQ(mode.exit_code, 2);
  EXPECT_NE(mode.err.find("stretch.mode"), std::string::npos) << mode.err;
  const auto contact =
      run_rbcsim("stretch --contact-diameter-um 30 --output '" + out + "'", scratch.path());
  EXPECT_EQ(contact.exit_code, 2);
  EXPECT_EQ(contact.err,
            "rbcsim: error: stretch.contact.diameter_um: the two contact patches overlap: too "
            "large for this cell\n");
  EXPECT_FALSE(fs::exists(out));
}

// The fluid mode on the level-2 cell (edges ~1 um) at dx = 2 um (S = 0.5, the paper's ratio): a
// 11 x 7 x 5 box, a third of plasma's viscosity and a loose steady criterion (this test is about
// the run directory; tests/cases/fluid_stretch_test.cpp about the physics). result.json names the
// mode, counts steps and passes its schema; the run directory holds the final flow field.
TEST(CliStretch, FluidModeWritesStepsAndTheFlowField) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(
      std::string("stretch ") + kCoarseCell +
          "--set lattice.spacing_um=2 --set stretch.fluid.kinematic_viscosity_m2_per_s=3.7e-7 "
          "--set stretch.fluid.steady_relative_rate_per_s=5 --mode fluid --forces 0,10 "
          "--threads 1 --json "
          "--output '" +
          run_dir.string() + "'",
      scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto printed = printed_run_result(result, run_dir, "stretch");
  const auto& stretch = printed["stretch"];
  EXPECT_EQ(stretch["mode"], "fluid");
  ASSERT_EQ(stretch["points"].size(), 2u);
  for (const auto& point : stretch["points"]) {
    EXPECT_TRUE(point["converged"].get<bool>());
    EXPECT_GT(point["steps"].get<int>(), 0);
    EXPECT_FALSE(point.contains("iterations"));
  }
  EXPECT_GT(stretch["points"][1]["axial_um"].get<double>(),
            stretch["points"][0]["axial_um"].get<double>());
  EXPECT_EQ(printed["files"]["fluid"], "fluid.vti");
  EXPECT_TRUE(fs::exists(run_dir / "fluid.vti"));
  EXPECT_TRUE(fs::exists(run_dir / "shapes/stretch_001.vtp"));
}

// A force the relaxation cannot reach in its budget: exit 1, the run directory still written,
// status "failed" with the reason, the failed point's shape kept for inspection.
TEST(CliStretch, UnreachedEquilibriumExitsOneAndRecordsTheFailure) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string("stretch ") + kCoarseCell +
                                     "--forces 0,10,20 --set stretch.quasi_static.max_iterations=3 "
                                     "--output '" +
                                     run_dir.string() + "'",
                                 scratch.path());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(
      result.err.rfind("rbcsim: failed: stretch: F = 10 pN: not converged after 3 iterations", 0),
      0u)
      << result.err;
  const auto written = read_json(run_dir / "result.json");
  EXPECT_EQ(written["status"], "failed");
  EXPECT_EQ(written["stretch"]["points"].size(), 2u);
  EXPECT_EQ(written["stretch"]["points"][1]["converged"], false);
  EXPECT_TRUE(fs::exists(run_dir / "shapes/stretch_001.vtp"));
}

}  // namespace
