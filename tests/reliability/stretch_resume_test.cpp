// Checkpoint and resume of the fluid-coupled stretch (docs/architecture.md): one simulation across
// all forces, the curve's progress (force index, ramp, start record, points so far) riding in its
// checkpoint. A run interrupted in the middle of a force reports the forces done; resumed from its
// checkpoint it ends with the straight run's result.json "stretch" object and stretch.csv, bit for
// bit (the wall times aside: they measure the machine). Also through the binary: --resume,
// Ctrl-C, a checkpoint of another config, and the quasi-static mode refusing the options.
//
// The level-2 discocyte (162 vertices) at dx = 2 um in a fluid of a third of plasma's viscosity,
// as in tests/cases/fluid_stretch_test.cpp, on one thread (the box has ~500 nodes), with a loose
// steady-state rule (50 /s over checks 1e-4 s apart, after a ramp of 2e-4 s) so that a force takes
// about 1000 steps: the physics is not tested here (tests/cases/fluid_stretch_test.cpp does), only
// that the run goes on where it stopped.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cases/stretch_output.hpp"
#include "common/interrupt.hpp"
#include "common/thread_count_scope.hpp"
#include "coupling/checkpoint.hpp"
#include "mesh/discocyte.hpp"
#include "support/interrupt_scope.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::cases {
namespace {

using rbcsim::testing::ScratchDirectory;

using rbcsim::testing::checkpoint_only_when_interrupted;
using rbcsim::testing::InterruptScope;

struct CoarseStretch {
  StretchCell cell = prepare_stretch_cell(mesh::discocyte_mesh({}, 2), {});
  membrane::MembraneModel model{cell.mesh, membrane::MembraneParameters{}};
  StretchSettings settings;

  CoarseStretch() {
    settings.mode = "fluid";
    settings.forces_pN = {0.0, 10.0, 20.0};
    settings.fluid.lattice.spacing_um = 2.0;
    settings.fluid.lattice.kinematic_viscosity_m2_per_s = 1.1e-6 / 3.0;
    settings.fluid.steady.relative_rate_per_s = 50.0;
    settings.fluid.steady.check_interval_s = 1e-4;
    settings.fluid.force_ramp_time_s = 2e-4;
  }
  StretchRun run(std::function<void(coupling::CoupledSimulation&)> configure) {
    settings.fluid.configure = std::move(configure);
    return run_stretch(model, cell, settings, {});
  }
};

// What result.json and stretch.csv hold of a run, its wall times zeroed.
struct Written {
  nlohmann::ordered_json section;
  std::vector<std::vector<double>> rows;
};

Written written(StretchRun run) {
  for (auto& point : run.points) point.wall_time_s = 0.0;
  Written out{stretch_result_section("fluid", {}, run.points, {}), {}};
  for (const auto& point : run.points) out.rows.push_back(stretch_table_row(point));
  return out;
}

TEST(StretchResume, InterruptedCurveResumesToTheStraightCurve) {
  const InterruptScope scope;
  const ThreadCountScope one_thread(1);
  CoarseStretch coarse;
  const auto straight = coarse.run({});
  ASSERT_TRUE(straight.ok()) << straight.failure;
  ASSERT_EQ(straight.points.size(), 3u);
  // Half-way through the second force, at an even step (the AA kernel's natural layout; see
  // tests/reliability/shear_resume_test.cpp). Measured: the odd step after it (661) resumes bit for
  // bit too, this box being periodic without the Lees-Edwards ghosts and wall links that make
  // odd steps round differently.
  const std::size_t interrupt_step =
      (straight.points[0].steps + straight.points[1].steps / 2) / 2 * 2;
  ASSERT_GT(interrupt_step, straight.points[0].steps);

  const ScratchDirectory scratch;
  const auto checkpoint = scratch.path() / coupling::kCheckpointFileName;
  const auto interrupted = coarse.run([&](coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, checkpoint, "stretch resume test");
    simulation.add_observer(
        {"interrupt", 1, [interrupt_step](const coupling::CoupledSimulation& s) {
           if (s.time_step() == interrupt_step) request_interrupt(SIGINT);
         }});
  });
  ASSERT_TRUE(interrupted.interrupted) << interrupted.failure;
  EXPECT_EQ(interrupted.failure.rfind("F = 10 pN: interrupted", 0), 0u) << interrupted.failure;
  ASSERT_EQ(interrupted.points.size(), 1u);  // the unfinished force is not a point
  ASSERT_TRUE(std::filesystem::exists(checkpoint));
  clear_interrupt();

  const auto resumed = coarse.run([&](coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, checkpoint, "stretch resume test");
    simulation.resume_from(checkpoint);
  });
  ASSERT_TRUE(resumed.ok()) << resumed.failure;
  EXPECT_FALSE(resumed.interrupted);
  // The first force was not run again: its point, wall time included, is the checkpoint's.
  EXPECT_EQ(resumed.points[0].wall_time_s, interrupted.points[0].wall_time_s);
  const auto resumed_files = written(resumed);
  const auto straight_files = written(straight);
  EXPECT_EQ(resumed_files.section, straight_files.section);
  EXPECT_EQ(resumed_files.rows, straight_files.rows);
}

// The binary's settings: the coarse stretch above.
const std::string kSettings =
    " --quiet --threads 1 --mode fluid --forces 0,10 --set mesh.subdivisions=2 --set "
    "mesh.method=parametric"
    " --set lattice.spacing_um=2 --set stretch.fluid.kinematic_viscosity_m2_per_s=3.6667e-7"
    " --set stretch.fluid.steady_relative_rate_per_s=50 --set "
    "stretch.fluid.steady_check_interval_s=1e-4"
    " --set stretch.fluid.force_ramp_time_s=2e-4";

nlohmann::json without_last_wall_time(nlohmann::json section) {
  section["points"].back().erase("wall_time_s");
  return section;
}

// stretch.csv without the wall time of its last row (the force run again).
std::string without_last_wall_time(const std::string& csv) {
  const auto last_row = csv.rfind('\n', csv.size() - 2) + 1;
  std::stringstream row(csv.substr(last_row));
  std::string cell;
  std::string kept;
  for (int column = 0; std::getline(row, cell, ','); ++column) {
    if (column != 7) kept += cell + ",";  // wall_time_s (stretch_table_columns)
  }
  return csv.substr(0, last_row) + kept;
}

// A straight run with --checkpoint-every leaves the checkpoint of its last force's last even
// hundred steps; --resume from it keeps the first force (its wall time is the first run's) and runs
// the last steps again, rewriting the same results and snapshot collection.
TEST(StretchResume, ResumeThroughTheBinaryRewritesTheSameResults) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const std::string settings = kSettings + " --set stretch.fluid.snapshot_interval_s=1e-4";
  const auto straight = rbcsim::testing::run_rbcsim(
      "stretch --checkpoint-every 100 --output '" + run_dir.string() + "'" + settings,
      scratch.path());
  ASSERT_EQ(straight.exit_code, 0) << straight.err;
  ASSERT_TRUE(std::filesystem::exists(run_dir / coupling::kCheckpointFileName));
  const auto straight_section = rbcsim::testing::read_json(run_dir / "result.json")["stretch"];
  const auto straight_csv = rbcsim::testing::read_text(run_dir / "stretch.csv");
  const auto straight_snapshots = rbcsim::testing::read_text(run_dir / "cell0.pvd");
  std::filesystem::remove(run_dir / "result.json");
  std::filesystem::remove(run_dir / "stretch.csv");

  const auto resumed = rbcsim::testing::run_rbcsim(
      "stretch --resume '" + run_dir.string() + "'" + settings, scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto result = rbcsim::testing::read_json(run_dir / "result.json");
  EXPECT_EQ(result["status"], "ok");
  const auto& section = result["stretch"];
  ASSERT_EQ(section["points"].size(), 2u);
  EXPECT_EQ(section["points"][0]["wall_time_s"], straight_section["points"][0]["wall_time_s"]);
  EXPECT_EQ(without_last_wall_time(section), without_last_wall_time(straight_section));
  EXPECT_EQ(without_last_wall_time(rbcsim::testing::read_text(run_dir / "stretch.csv")),
            without_last_wall_time(straight_csv));
  EXPECT_TRUE(std::filesystem::exists(run_dir / "shapes" / "stretch_000.vtp"));
  EXPECT_TRUE(std::filesystem::exists(run_dir / "shapes" / "stretch_001.vtp"));
  // The snapshot collection goes on from the first run's, before and after the checkpoint.
  EXPECT_GT(std::count(straight_snapshots.begin(), straight_snapshots.end(), '\n'), 10);
  EXPECT_EQ(rbcsim::testing::read_text(run_dir / "cell0.pvd"), straight_snapshots);
}

// Ctrl-C (SIGINT once the first force's shape is written) on a curve of 41 forces of at most
// 1e-3 s each: the forces done so far in result.json (status "interrupted") and stretch.csv, a
// checkpoint, exit code 130.
TEST(StretchResume, SigintWritesTheForcesDoneSoFarAndACheckpoint) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  EXPECT_EQ(rbcsim::testing::run_rbcsim_signalled_once(
                run_dir / "shapes" / "stretch_000.vtp",
                "stretch --quiet --threads 1 --mode fluid --forces 0:40/41"
                " --set mesh.subdivisions=2 --set mesh.method=parametric --set lattice.spacing_um=2"
                " --set stretch.fluid.kinematic_viscosity_m2_per_s=3.6667e-7"
                " --set stretch.fluid.max_time_per_force_s=1e-3 --output '" +
                    run_dir.string() + "'"),
            130);
  const auto result = rbcsim::testing::read_json(run_dir / "result.json");
  EXPECT_EQ(result["status"], "interrupted");
  const auto point_count = result["stretch"]["points"].size();
  EXPECT_GE(point_count, 1u);
  EXPECT_LT(point_count, 41u);
  const auto csv = rbcsim::testing::read_text(run_dir / "stretch.csv");
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), point_count + 1);
  EXPECT_TRUE(std::filesystem::exists(run_dir / coupling::kCheckpointFileName));
}

// A resume with another config is refused with one line naming the run's config.json and the
// option that differs, before anything is written.
TEST(StretchResume, AnotherConfigThanTheRunsIsBadInput) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  ASSERT_EQ(rbcsim::testing::run_rbcsim(
                "stretch --checkpoint-every 100 --output '" + run_dir.string() + "'" + kSettings,
                scratch.path())
                .exit_code,
            0);
  const auto config_json = rbcsim::testing::read_text(run_dir / "config.json");
  const auto resumed =
      rbcsim::testing::run_rbcsim("stretch --resume '" + run_dir.string() + "'" + kSettings +
                                      " --set stretch.fluid.box_margin_um=4",
                                  scratch.path());
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_EQ(std::count(resumed.err.begin(), resumed.err.end(), '\n'), 1) << resumed.err;
  EXPECT_NE(resumed.err.find("config.json"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("stretch.fluid.box_margin_um"), std::string::npos) << resumed.err;
  EXPECT_EQ(rbcsim::testing::read_text(run_dir / "config.json"), config_json);
}

// The quasi-static mode takes seconds and has nothing to checkpoint: it refuses the options with
// one line, before writing anything.
TEST(StretchResume, TheQuasiStaticModeRefusesCheckpointOptions) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  for (const std::string& option : {"--checkpoint-every 100 --output '" + run_dir.string() + "'",
                                    "--resume '" + run_dir.string() + "'"}) {
    SCOPED_TRACE(option);
    const auto refused = rbcsim::testing::run_rbcsim(
        "stretch --quiet --forces 0 --set mesh.subdivisions=2 --set mesh.method=parametric " +
            option,
        scratch.path());
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_NE(refused.err.find(option.substr(0, option.find(' '))), std::string::npos)
        << refused.err;
    EXPECT_NE(refused.err.find("only the fluid mode"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(run_dir));
  }
}

}  // namespace
}  // namespace rbcsim::cases
