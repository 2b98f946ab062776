// Checkpoint and resume of the shear sweep (docs/architecture.md): each rate checkpoints in its own
// rate_<i>/ directory; a sweep interrupted in the middle of a rate reports the rates done so far
// and the interrupted ones as such; resumed, the finished rates are kept and the interrupted one
// continues from its checkpoint to the straight run's point, bit for bit (the tank-treading record
// and the steady-state checks ride in the checkpoint). Also through the binary with
// --checkpoint-every and --resume. The coarse sweep of shear_case_test.cpp, one unit of strain.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/shear_case.hpp"
#include "common/interrupt.hpp"
#include "common/wall_clock.hpp"
#include "coupling/checkpoint.hpp"
#include "mesh/cell_shapes.hpp"
#include "support/interrupt_scope.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::cases {
namespace {

using rbcsim::testing::ScratchDirectory;

// Rate 1 (500 1/s) takes about 230 steps. An odd step: the optimised fluid kernel then holds its
// populations post-collision in the swapped (AA) layout, which the checkpoint restores as is.
constexpr std::size_t kShearInterruptStep =
    181;  // past half the run: tank treading is measured there

// Rate 1 sleeps this long before it is interrupted: time the resumed rate must still count.
constexpr auto kSleepBeforeInterrupt = std::chrono::milliseconds(300);
constexpr double kSleptSeconds = 0.3;

using rbcsim::testing::checkpoint_only_when_interrupted;
using rbcsim::testing::InterruptScope;

const mesh::TriangleMesh& coarse_cell() {
  static const mesh::TriangleMesh cell = in_shear_frame(mesh::generate_cell("discocyte", 3));
  return cell;
}

// Rates 0 and 500 1/s for one unit of strain, on the 1 um lattice in a small box.
struct CoarseSweep {
  membrane::MembraneModel model{coarse_cell(), membrane::MembraneParameters{}};
  ShearSettings settings;
  ShearEngine engine;

  CoarseSweep() {
    engine.lattice = {1.0, 1.0, 1025.0, 1.1e-6};
    settings.rates_per_s = {0.0, 500.0};
    settings.max_strain = 1.0;
    settings.max_reynolds_number = 0.4;
    settings.width_diameters = 1.6;
    settings.gap_diameters = 2.0;
  }
  std::vector<ShearPoint> sweep(const ShearHooks& hooks) const {
    const auto plans = plan_shear_rates(model, coarse_cell(), engine, settings);
    return run_shear_sweep(model, coarse_cell(), engine, settings, plans, 1, hooks);
  }
};

// The coarse sweep's setting through the binary (the rates and strain added per test).
constexpr const char* kCoarseBinarySettings =
    " --quiet --threads 1 --set mesh.subdivisions=3 --set lattice.spacing_um=1"
    " --set shear.max_reynolds_number=0.4 --set shear.width_diameters=1.6"
    " --set shear.gap_diameters=2";

std::filesystem::path checkpoint_of(const ScratchDirectory& scratch, std::size_t rate_index) {
  return scratch.path() / (shear_rate_directory(rate_index) + ".bin");
}

void expect_same(const ShearPoint& resumed, const ShearPoint& straight) {
  EXPECT_EQ(resumed.failure, straight.failure);
  EXPECT_EQ(resumed.steps, straight.steps);
  EXPECT_EQ(resumed.strain, straight.strain);
  EXPECT_EQ(resumed.stop_reason, straight.stop_reason);
  EXPECT_EQ(resumed.steady, straight.steady);
  EXPECT_EQ(resumed.force_cap_steps, straight.force_cap_steps);
  EXPECT_EQ(resumed.shape.length_um, straight.shape.length_um);
  EXPECT_EQ(resumed.shape.breadth_um, straight.shape.breadth_um);
  EXPECT_EQ(resumed.shape.inclination_deg, straight.shape.inclination_deg);
  EXPECT_EQ(resumed.smoothness_rad, straight.smoothness_rad);
  EXPECT_EQ(resumed.roughness_rad, straight.roughness_rad);
  EXPECT_EQ(resumed.area_strain.total_relative_change, straight.area_strain.total_relative_change);
  EXPECT_EQ(resumed.area_strain.max_abs_triangle_deviation,
            straight.area_strain.max_abs_triangle_deviation);
  EXPECT_EQ(resumed.tank_treading_hz, straight.tank_treading_hz);
  ASSERT_EQ(resumed.history.size(), straight.history.size());
  for (std::size_t i = 0; i < straight.history.size(); ++i) {
    EXPECT_EQ(resumed.history[i].strain, straight.history[i].strain) << i;
    EXPECT_EQ(resumed.history[i].shape.length_um, straight.history[i].shape.length_um) << i;
    EXPECT_EQ(resumed.history[i].shape.breadth_um, straight.history[i].shape.breadth_um) << i;
  }
}

TEST(ShearResume, InterruptedSweepResumesToTheStraightSweep) {
  const InterruptScope scope;
  const CoarseSweep coarse;
  const auto straight = coarse.sweep({});
  ASSERT_EQ(straight.size(), 2u);
  ASSERT_EQ(straight[1].failure, "");
  ASSERT_GT(straight[1].steps, kShearInterruptStep);
  ASSERT_NE(straight[1].tank_treading_hz, 0.0);
  ASSERT_GT(straight[1].history.size(), 2u);  // samples before and after the interrupt

  // Rate 0 ends; rate 1 is interrupted at kShearInterruptStep and checkpoints there.
  const ScratchDirectory scratch;
  ShearHooks first;
  first.configure = [&scratch](std::size_t rate, coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, checkpoint_of(scratch, rate), "shear resume test");
    simulation.add_observer({"interrupt", 1, [rate](const coupling::CoupledSimulation& s) {
                               if (rate == 1 && s.time_step() == 1) {
                                 std::this_thread::sleep_for(kSleepBeforeInterrupt);
                               }
                               if (rate == 1 && s.time_step() == kShearInterruptStep) {
                                 request_interrupt(SIGINT);
                               }
                             }});
  };
  const auto interrupted = coarse.sweep(first);
  EXPECT_FALSE(interrupted[0].interrupted);
  ASSERT_TRUE(interrupted[1].interrupted) << interrupted[1].failure;
  EXPECT_EQ(interrupted[1].steps, kShearInterruptStep);
  EXPECT_GE(interrupted[1].wall_time_s, kSleptSeconds);
  ASSERT_TRUE(std::filesystem::exists(checkpoint_of(scratch, 1)));

  // Still interrupted: the rates not started are reported so, not run.
  const auto unstarted = coarse.sweep(first);
  EXPECT_TRUE(unstarted[0].interrupted);
  EXPECT_EQ(unstarted[0].steps, 0u);
  clear_interrupt();

  ShearHooks second;
  second.completed = {interrupted[0], std::nullopt};
  second.configure = [&scratch](std::size_t rate, coupling::CoupledSimulation& simulation) {
    ASSERT_EQ(rate, 1u) << "a completed rate ran again";
    checkpoint_only_when_interrupted(simulation, checkpoint_of(scratch, rate), "shear resume test");
    simulation.resume_from(checkpoint_of(scratch, rate));
  };
  const auto resume_started = WallClock::now();
  const auto resumed = coarse.sweep(second);
  const double resumed_sweep_s = seconds_since(resume_started);
  ASSERT_EQ(resumed.size(), 2u);
  for (std::size_t i = 0; i < resumed.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_FALSE(resumed[i].interrupted);
    expect_same(resumed[i], straight[i]);
  }
  // Rate 1's wall time goes on from the checkpoint's: the sleep before the interrupt counts, so
  // the rate took longer than the whole resumed sweep.
  EXPECT_GE(resumed[1].wall_time_s, interrupted[1].wall_time_s);
  EXPECT_GT(resumed[1].wall_time_s, resumed_sweep_s);
}

// Through the binary: a straight run with --checkpoint-every leaves each rate's last checkpoint
// and point.json. Taking rate 1's point.json away makes it a rate interrupted at its last
// checkpoint; --resume keeps rate 0 (not run again: its wall time is the first run's) and runs
// rate 1's last steps again, rewriting the same results (rate 1 ends at step 230; its last
// checkpoint is at step 219, odd).
TEST(ShearResume, ResumeThroughTheBinaryKeepsFinishedRatesAndRewritesTheSameResults) {
  const ScratchDirectory scratch;
  const std::string settings = std::string(" --rates 0,500 --max-strain 1") + kCoarseBinarySettings;
  const auto run_dir = scratch.path() / "run";
  const auto straight = rbcsim::testing::run_rbcsim(
      "shear --checkpoint-every 73 --output '" + run_dir.string() + "'" + settings, scratch.path());
  ASSERT_EQ(straight.exit_code, 0) << straight.err;
  const auto rate_1 = run_dir / shear_rate_directory(1);
  ASSERT_TRUE(std::filesystem::exists(rate_1 / coupling::kCheckpointFileName));
  const auto result_of = [&run_dir] { return rbcsim::testing::read_json(run_dir / "result.json"); };
  auto straight_shear = result_of()["shear"];
  std::filesystem::remove(run_dir / "result.json");
  std::filesystem::remove(run_dir / "shear.csv");
  ASSERT_TRUE(std::filesystem::remove(rate_1 / "point.json"));

  const auto resumed = rbcsim::testing::run_rbcsim(
      "shear --resume '" + run_dir.string() + "'" + settings, scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  auto resumed_shear = result_of()["shear"];
  EXPECT_EQ(resumed_shear["rates"][0]["wall_time_s"], straight_shear["rates"][0]["wall_time_s"]);
  for (auto* shear : {&straight_shear, &resumed_shear}) (*shear)["rates"][1].erase("wall_time_s");
  EXPECT_EQ(resumed_shear, straight_shear);
  EXPECT_TRUE(std::filesystem::exists(run_dir / "shear.csv"));
}

// Ctrl-C (here SIGINT once the rate has started, its rate_000/ created; the cell at 100 1/s,
// never steady with a tolerance of 1e-12, would run 1000 strains): the rates done so far (none) in
// result.json with status "interrupted", the interrupted rate's checkpoint, exit code 130.
TEST(ShearResume, SigintWritesTheRatesDoneSoFarAndACheckpoint) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  EXPECT_EQ(rbcsim::testing::run_rbcsim_signalled_once(
                run_dir / shear_rate_directory(0),
                std::string("shear --rates 100 --max-strain 1000") +
                    " --set shear.steady_tolerance_per_strain=1e-12" + kCoarseBinarySettings +
                    " --output '" + run_dir.string() + "'"),
            130);
  const auto result = rbcsim::testing::read_json(run_dir / "result.json");
  EXPECT_EQ(result["status"], "interrupted");
  const auto& rates = result["shear"]["rates"];
  EXPECT_EQ(rates.size(), 0u);
  EXPECT_TRUE(
      std::filesystem::exists(run_dir / shear_rate_directory(0) / coupling::kCheckpointFileName));
  EXPECT_TRUE(std::filesystem::exists(run_dir / "shear.csv"));
}

// Interrupted in its first rate and resumed, the run's wall_time_s adds the interrupted run's
// (wall_time_before_resume_s, read from the result.json it left).
TEST(ShearResume, ResumedRunCountsTheWallTimeOfTheInterruptedOne) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const std::string settings = std::string(" --rates 0,500 --max-strain 1") + kCoarseBinarySettings;
  ASSERT_EQ(rbcsim::testing::run_rbcsim_signalled_once(
                run_dir / shear_rate_directory(0),
                "shear --output '" + run_dir.string() + "'" + settings),
            130);
  const auto interrupted = rbcsim::testing::read_json(run_dir / "result.json");
  ASSERT_EQ(interrupted["status"], "interrupted");
  EXPECT_FALSE(interrupted.contains("wall_time_before_resume_s"));
  const double interrupted_s = interrupted["wall_time_s"].get<double>();

  const auto resumed_run = rbcsim::testing::run_rbcsim(
      "shear --resume '" + run_dir.string() + "'" + settings, scratch.path());
  ASSERT_EQ(resumed_run.exit_code, 0) << resumed_run.err;
  const auto resumed = rbcsim::testing::read_json(run_dir / "result.json");
  EXPECT_EQ(resumed["status"], "ok");
  EXPECT_EQ(resumed["wall_time_before_resume_s"].get<double>(), interrupted_s);
  EXPECT_GT(resumed["wall_time_s"].get<double>(), interrupted_s);
}

// One finished rate of the coarse binary settings in <scratch>/run, and the resume of it with
// shear.gap_diameters changed (before which `prepare` may alter the run directory).
rbcsim::testing::RunResult resume_with_another_gap(
    const ScratchDirectory& scratch,
    const std::function<void(const std::filesystem::path&)>& prepare) {
  const auto run_dir = scratch.path() / "run";
  const std::string settings = std::string(" --rates 0 --max-strain 0.2") + kCoarseBinarySettings;
  EXPECT_EQ(rbcsim::testing::run_rbcsim("shear --output '" + run_dir.string() + "'" + settings,
                                        scratch.path())
                .exit_code,
            0);
  prepare(run_dir);
  return rbcsim::testing::run_rbcsim(
      "shear --resume '" + run_dir.string() + "'" + settings + " --set shear.gap_diameters=2.5",
      scratch.path());
}

// A resume with another option than the run was started with names that option and its two
// values in one line, and writes nothing.
TEST(ShearResume, AnotherConfigThanTheRunsIsBadInputNamingTheKey) {
  const ScratchDirectory scratch;
  std::string config_json;
  const auto resumed = resume_with_another_gap(scratch, [&](const std::filesystem::path& run) {
    config_json = rbcsim::testing::read_text(run / "config.json");
  });
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_EQ(std::count(resumed.err.begin(), resumed.err.end(), '\n'), 1) << resumed.err;
  EXPECT_NE(resumed.err.find("config.json"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("shear.gap_diameters = 2,"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("gives 2.5"), std::string::npos) << resumed.err;
  EXPECT_EQ(rbcsim::testing::read_text(scratch.path() / "run" / "config.json"), config_json);
}

// Without the run's config.json to compare with, a finished point's own fingerprint still
// refuses another config.
TEST(ShearResume, APointOfAnotherConfigIsBadInput) {
  const ScratchDirectory scratch;
  const auto resumed = resume_with_another_gap(scratch, [](const std::filesystem::path& run) {
    std::filesystem::remove(run / "config.json");
  });
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.err.find("point.json"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("different config"), std::string::npos) << resumed.err;
}

}  // namespace
}  // namespace rbcsim::cases
