// Checkpoint and resume of the capillary experiment (docs/architecture.md): a run interrupted after
// kCapillaryInterruptStep steps, then resumed from its checkpoint, ends with the straight run's
// samples, deformation record and step counts bit for bit (although the interrupted run's observers
// saw a state between two sample intervals), also through the binary with --checkpoint-every and
// --resume.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/capillary_case.hpp"
#include "common/interrupt.hpp"
#include "config/config.hpp"
#include "coupling/checkpoint.hpp"
#include "setup/capillary_from_config.hpp"
#include "setup/cell_from_config.hpp"
#include "support/interrupt_scope.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::cases {
namespace {

using rbcsim::testing::ScratchDirectory;

constexpr std::size_t kTotalSteps = 30;
constexpr std::size_t kSampleSteps = 4;
// Odd, so the optimised fluid kernel holds its populations post-collision in the swapped (AA)
// layout there, and not a multiple of kSampleSteps.
constexpr std::size_t kCapillaryInterruptStep = 13;

using rbcsim::testing::checkpoint_only_when_interrupted;
using rbcsim::testing::InterruptScope;

// The coarse capillary of capillary_case_test.cpp (dx = 1 um, the 162-vertex cell).
const std::vector<std::string> kCoarseAssignments = {"mesh.subdivisions=2",
                                                     "mesh.method=parametric",
                                                     "lattice.spacing_um=1",
                                                     "capillary.throat_diameter_um=9",
                                                     "capillary.inlet_velocity_m_per_s=0.014",
                                                     "capillary.fluid_tolerance=1e-5"};

// The coarse capillary run for kTotalSteps steps with a sample every kSampleSteps.
class CoarseCapillary {
 public:
  CoarseCapillary()
      : config_(config::resolve_config({.assignments = kCoarseAssignments})),
        wall_(setup::capillary_wall_from(config_)),
        cell_(setup::cell_mesh_from(config_)) {}

  CapillaryRun run(const CapillaryConfigure& configure) const {
    const auto physics = setup::capillary_physics_from(config_, wall_, cell_.mesh, {});
    auto settings = setup::capillary_settings_from(config_, wall_);
    const double dt_s = dt_s_of();
    settings.max_time_s = (static_cast<double>(kTotalSteps) - 0.5) * dt_s;
    settings.sample_interval_s = static_cast<double>(kSampleSteps) * dt_s;
    return run_capillary(cell_.mesh, physics, settings, configure);
  }

  double dt_s_of() const {
    return setup::capillary_physics_from(config_, wall_, cell_.mesh, {}).units.dt_s();
  }

 private:
  config::Config config_;
  setup::CapillaryWall wall_;
  setup::CellMesh cell_;
};

void expect_same(const Vec3& resumed, const Vec3& straight) {
  for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(resumed[axis], straight[axis]);
}

void expect_same(const CapillarySample& resumed, const CapillarySample& straight) {
  EXPECT_EQ(resumed.time_s, straight.time_s);
  expect_same(resumed.centroid_um, straight.centroid_um);
  EXPECT_EQ(resumed.velocity_x_m_per_s, straight.velocity_x_m_per_s);
  EXPECT_EQ(resumed.deformation_index, straight.deformation_index);
  expect_same(resumed.extents_um, straight.extents_um);
  EXPECT_EQ(resumed.area_strain.total_relative_change, straight.area_strain.total_relative_change);
  EXPECT_EQ(resumed.area_strain.max_abs_triangle_deviation,
            straight.area_strain.max_abs_triangle_deviation);
}

TEST(CapillaryResume, InterruptedThenResumedRunEndsAsAStraightRun) {
  const InterruptScope scope;
  const CoarseCapillary capillary;
  const auto straight = capillary.run({});
  ASSERT_EQ(straight.steps, kTotalSteps) << straight.stop_reason;

  const ScratchDirectory scratch;
  const auto file = scratch.path() / coupling::kCheckpointFileName;
  const auto interrupted = capillary.run([&file](coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, file, "capillary resume test");
    simulation.add_observer({"interrupt", 1, [](const coupling::CoupledSimulation& s) {
                               if (s.time_step() == kCapillaryInterruptStep)
                                 request_interrupt(SIGINT);
                             }});
  });
  ASSERT_TRUE(interrupted.interrupted) << interrupted.failure;
  EXPECT_EQ(interrupted.steps, kCapillaryInterruptStep);
  // The results so far include the state reached, between two sample intervals.
  ASSERT_EQ(interrupted.samples.size(), kCapillaryInterruptStep / kSampleSteps + 2);
  EXPECT_EQ(interrupted.samples.back().time_s, interrupted.time_s);
  ASSERT_TRUE(std::filesystem::exists(file));
  clear_interrupt();

  const auto resumed = capillary.run([&file](coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, file, "capillary resume test");
    simulation.resume_from(file);
  });
  ASSERT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.steps, straight.steps);
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.stop_reason, straight.stop_reason);
  EXPECT_EQ(resumed.force_capped_steps, straight.force_capped_steps);
  EXPECT_EQ(resumed.initial_deformation_index, straight.initial_deformation_index);
  EXPECT_EQ(resumed.peak_deformation_index, straight.peak_deformation_index);
  EXPECT_EQ(resumed.peak_time_s, straight.peak_time_s);
  EXPECT_EQ(resumed.peak_centroid_x_um, straight.peak_centroid_x_um);
  EXPECT_EQ(resumed.final_deformation_index, straight.final_deformation_index);
  EXPECT_EQ(resumed.final_centroid_x_um, straight.final_centroid_x_um);
  EXPECT_EQ(resumed.entry_time_s.has_value(), straight.entry_time_s.has_value());
  EXPECT_EQ(resumed.exit_time_s.has_value(), straight.exit_time_s.has_value());
  ASSERT_EQ(resumed.samples.size(), straight.samples.size());
  for (std::size_t i = 0; i < straight.samples.size(); ++i) {
    SCOPED_TRACE(i);
    expect_same(resumed.samples[i], straight.samples[i]);
  }
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// The binary's options for the coarse run of kTotalSteps steps, with a sample and a membrane
// snapshot every kSampleSteps and a fluid snapshot every 2 kSampleSteps.
std::string coarse_binary_settings() {
  const double dt_s = CoarseCapillary().dt_s_of();
  std::string settings = " --quiet --threads 1";
  for (const auto& assignment : kCoarseAssignments) settings += " --set " + assignment;
  settings +=
      " --set capillary.max_time_s=" +
      number_text((static_cast<double>(kTotalSteps) - 0.5) * dt_s) +
      " --set capillary.sample_interval_s=" +
      number_text(static_cast<double>(kSampleSteps) * dt_s) +
      " --set output.membrane_interval_s=" + number_text(static_cast<double>(kSampleSteps) * dt_s) +
      " --set output.fluid_interval_s=" + number_text(static_cast<double>(2 * kSampleSteps) * dt_s);
  return settings;
}

// The coarse run through the binary with --checkpoint-every 9: it leaves its last checkpoint
// (step 27 of 30, odd) in run_dir.
void run_with_checkpoints(const ScratchDirectory& scratch, const std::filesystem::path& run_dir,
                          const std::string& settings) {
  const auto straight = rbcsim::testing::run_rbcsim(
      "capillary --checkpoint-every 9 --output '" + run_dir.string() + "'" + settings,
      scratch.path());
  // 30 steps leave the cell upstream of the narrow section: a "failed" run (exit 1).
  ASSERT_EQ(straight.exit_code, 1) << straight.err;
  ASSERT_TRUE(std::filesystem::exists(run_dir / coupling::kCheckpointFileName));
}

// Through the binary: --resume of a directory left by run_with_checkpoints runs the last steps
// again and must rewrite the same result.json "capillary" object, capillary_timeseries.csv and
// snapshot collections.
TEST(CapillaryResume, ResumeThroughTheBinaryRewritesTheSameResults) {
  const ScratchDirectory scratch;
  const std::string settings = coarse_binary_settings();
  const auto run_dir = scratch.path() / "run";
  ASSERT_NO_FATAL_FAILURE(run_with_checkpoints(scratch, run_dir, settings));
  const auto straight_result =
      nlohmann::json::parse(rbcsim::testing::read_text(run_dir / "result.json"));
  const auto straight_rows = rbcsim::testing::read_lines(run_dir / "capillary_timeseries.csv");
  const auto straight_cells = rbcsim::testing::read_lines(run_dir / "cell0.pvd");
  const auto straight_fluid = rbcsim::testing::read_lines(run_dir / "fluid.pvd");
  std::filesystem::remove(run_dir / "result.json");
  std::filesystem::remove(run_dir / "capillary_timeseries.csv");

  const auto resumed = rbcsim::testing::run_rbcsim(
      "capillary --resume '" + run_dir.string() + "'" + settings, scratch.path());
  ASSERT_EQ(resumed.exit_code, 1) << resumed.err;
  const auto resumed_result =
      nlohmann::json::parse(rbcsim::testing::read_text(run_dir / "result.json"));
  EXPECT_EQ(resumed_result["capillary"], straight_result["capillary"]);
  EXPECT_EQ(rbcsim::testing::read_lines(run_dir / "capillary_timeseries.csv"), straight_rows);
  // The collections go on from the interrupted run's: every snapshot, before and after step 27.
  EXPECT_GT(straight_cells.size(), 10u);
  EXPECT_EQ(rbcsim::testing::read_lines(run_dir / "cell0.pvd"), straight_cells);
  EXPECT_EQ(rbcsim::testing::read_lines(run_dir / "fluid.pvd"), straight_fluid);
}

// A snapshot collection the resumed run cannot continue is bad input: one line naming it, exit 2,
// and the interrupted run's files as they were.
TEST(CapillaryResume, AMalformedSnapshotCollectionIsBadInput) {
  const ScratchDirectory scratch;
  const std::string settings = coarse_binary_settings();
  const auto run_dir = scratch.path() / "run";
  ASSERT_NO_FATAL_FAILURE(run_with_checkpoints(scratch, run_dir, settings));
  const std::string truncated = rbcsim::testing::read_text(run_dir / "cell0.pvd").substr(0, 120);
  rbcsim::testing::write_file(run_dir / "cell0.pvd", truncated);
  const auto result_before = rbcsim::testing::read_text(run_dir / "result.json");

  const auto resumed = rbcsim::testing::run_rbcsim(
      "capillary --resume '" + run_dir.string() + "'" + settings, scratch.path());
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.err.find("cell0.pvd"), std::string::npos) << resumed.err;
  EXPECT_EQ(std::count(resumed.err.begin(), resumed.err.end(), '\n'), 1) << resumed.err;
  EXPECT_EQ(rbcsim::testing::read_text(run_dir / "cell0.pvd"), truncated);
  EXPECT_EQ(rbcsim::testing::read_text(run_dir / "result.json"), result_before);
}

TEST(CapillaryResume, AMissingCheckpointIsBadInputAndLeavesNoFile) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  std::string settings;
  for (const auto& assignment : kCoarseAssignments) settings += " --set " + assignment;
  const auto resumed = rbcsim::testing::run_rbcsim(
      "capillary --quiet --resume '" + run_dir.string() + "'" + settings, scratch.path());
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.err.find("checkpoint.bin"), std::string::npos) << resumed.err;
  EXPECT_FALSE(std::filesystem::exists(run_dir));
}

}  // namespace
}  // namespace rbcsim::cases
