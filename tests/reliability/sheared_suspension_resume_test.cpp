// Checkpoint and resume of a sheared suspension (cases/sheared_suspension.hpp): a run interrupted
// after kInterruptStep steps, between two sample intervals, then resumed from its checkpoint, ends
// with the straight run's samples, cell samples and counts bit for bit; and the record a finished
// rate keeps (sheared_suspension_record) reads back as the run it was. Through the binary:
// tests/cli_shear/cli_shear_test.cpp. (A named namespace: the unity build merges this file with
// the other resume tests.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cases/sheared_suspension.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "config/config.hpp"
#include "coupling/checkpoint.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/suspension_from_config.hpp"
#include "support/expect_each.hpp"
#include "support/interrupt_scope.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::cases {
namespace sheared_suspension_resume {

using rbcsim::testing::expect_each_same;
using rbcsim::testing::interrupt_after_step;
using rbcsim::testing::InterruptScope;
using rbcsim::testing::resume_from_checkpoint;
using rbcsim::testing::ScratchDirectory;

constexpr std::size_t kTotalSteps = 30;
constexpr std::size_t kSampleSteps = 4;
// Odd (the optimised kernel's swapped layout) and not a multiple of kSampleSteps.
constexpr std::size_t kInterruptStep = 13;

// Two coarse discocytes (162 vertices, dx = 1 um) side by side in mid-gap, edge-on to the flow,
// in a 12 um gap of a 16 x 10 um periodic box, at a physical 200 1/s, compressed as the command
// compresses it.
class TwoShearedCells {
 public:
  TwoShearedCells()
      : request_{.assignments = {"mesh.subdivisions=2", "mesh.method=parametric",
                                 "lattice.spacing_um=1", "suspension.contact_range_um=1.75",
                                 R"(suspension.cells=[
                                     {"morphology": "discocyte", "centre_um": [4, 0, 5],
                                      "axis": [1, 0, 0]},
                                     {"morphology": "discocyte", "centre_um": [12, 0.5, 5],
                                      "axis": [1, 0, 0]}])"}},
        config_(config::resolve_config(request_)) {}

  ShearedSuspensionRun run(const SuspensionConfigure& configure) const {
    const double diameter_um = 7.82;
    const double rate_per_s = 200.0;
    const double factor =
        setup::sheared_suspension_compression_from(config_, rate_per_s, diameter_um).factor;
    const auto simulated = setup::compressed_suspension_config(config_, factor);
    const auto mix = setup::suspension_mix_from(simulated);
    const auto morphologies = setup::suspension_morphologies_from(request_, mix, factor);
    const SuspensionPhysics physics{setup::fluid_parameters_from(simulated),
                                    setup::coupling_parameters_from(simulated, {}),
                                    config::make_unit_converter(simulated)};
    const double simulated_rate_per_s = rate_per_s * factor;
    auto settings =
        setup::sheared_suspension_settings_from(simulated, diameter_um, simulated_rate_per_s);
    settings.gap_um = 12.0;
    settings.length_um = 16.0;
    settings.width_um = 10.0;
    const double dt_s = physics.units.dt_s();
    settings.strain = (static_cast<double>(kTotalSteps) - 0.5) * dt_s * simulated_rate_per_s;
    settings.sample_interval_strain =
        static_cast<double>(kSampleSteps) * dt_s * simulated_rate_per_s;
    const std::vector<std::size_t> cells{0, 0};
    return run_sheared_suspension(morphologies, cells, physics, settings, configure);
  }

 private:
  config::ConfigRequest request_;
  config::Config config_;
};

void expect_same(const ShearedSuspensionSample& resumed, const ShearedSuspensionSample& straight) {
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.strain, straight.strain);
  EXPECT_EQ(resumed.relative_viscosity, straight.relative_viscosity);
  EXPECT_EQ(resumed.particle_stress_Pa, straight.particle_stress_Pa);
  EXPECT_EQ(resumed.cytoplasm_stress_Pa, straight.cytoplasm_stress_Pa);
  EXPECT_EQ(resumed.near_wall_relative_viscosity, straight.near_wall_relative_viscosity);
  EXPECT_EQ(resumed.contact_pairs, straight.contact_pairs);
  EXPECT_EQ(resumed.pierced_cells, straight.pierced_cells);
}

void expect_same(const ShearedSuspensionCellSample& resumed,
                 const ShearedSuspensionCellSample& straight) {
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.cell, straight.cell);
  EXPECT_EQ(resumed.centroid_um, straight.centroid_um);
  EXPECT_EQ(resumed.deformation_index, straight.deformation_index);
}

void expect_same(const ShearedSuspensionRun& resumed, const ShearedSuspensionRun& straight) {
  EXPECT_EQ(resumed.cell_morphologies, straight.cell_morphologies);
  EXPECT_EQ(resumed.packed_hematocrit, straight.packed_hematocrit);
  EXPECT_EQ(resumed.steps, straight.steps);
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.stop_reason, straight.stop_reason);
  EXPECT_EQ(resumed.close_contact_steps, straight.close_contact_steps);
  EXPECT_EQ(resumed.capped_contact_steps, straight.capped_contact_steps);
  EXPECT_EQ(resumed.samples_with_pierced_cells, straight.samples_with_pierced_cells);
  EXPECT_EQ(resumed.averaged_samples, straight.averaged_samples);
  EXPECT_EQ(resumed.relative_viscosity, straight.relative_viscosity);
  EXPECT_EQ(resumed.relative_viscosity_sd, straight.relative_viscosity_sd);
  EXPECT_EQ(resumed.near_wall_relative_viscosity, straight.near_wall_relative_viscosity);
  const auto same = [](const auto& a, const auto& b) { expect_same(a, b); };
  expect_each_same(resumed.samples, straight.samples, same);
  expect_each_same(resumed.cell_samples, straight.cell_samples, same);
}

TEST(ShearedSuspensionResume, InterruptedThenResumedRunEndsAsAStraightRun) {
  const InterruptScope scope;
  const TwoShearedCells suspension;
  const auto straight = suspension.run({});
  ASSERT_TRUE(straight.ok()) << straight.failure;
  ASSERT_EQ(straight.steps, kTotalSteps) << straight.stop_reason;
  // Every kSampleSteps from step 0, and the final state (step 30).
  ASSERT_EQ(straight.samples.size(), kTotalSteps / kSampleSteps + 2);
  // The cells moved and stressed the fluid: the comparison below compares something.
  EXPECT_NE(straight.samples.back().particle_stress_Pa, 0.0);

  const ScratchDirectory scratch;
  const auto file = scratch.path() / coupling::kCheckpointFileName;
  const auto interrupted =
      suspension.run(interrupt_after_step(kInterruptStep, file, "sheared suspension resume test"));
  ASSERT_TRUE(interrupted.interrupted) << interrupted.failure;
  EXPECT_EQ(interrupted.steps, kInterruptStep);
  // The results so far include the state reached, between two sample intervals.
  ASSERT_EQ(interrupted.samples.size(), kInterruptStep / kSampleSteps + 2);
  EXPECT_EQ(interrupted.samples.back().time_s, interrupted.time_s);
  EXPECT_EQ(interrupted.cell_samples.size(), 2 * interrupted.samples.size());
  ASSERT_TRUE(std::filesystem::exists(file));
  clear_interrupt();

  const auto resumed =
      suspension.run(resume_from_checkpoint(file, "sheared suspension resume test"));
  ASSERT_TRUE(resumed.ok()) << resumed.failure;
  expect_same(resumed, straight);

  // The finished run's record reads back as the run, to the last bit.
  const auto record = nlohmann::json::parse(sheared_suspension_record(straight).dump());
  const auto read = sheared_suspension_from_record(record, "point.json");
  expect_same(read, straight);
  EXPECT_EQ(read.gap_um, straight.gap_um);
  EXPECT_EQ(read.plasma_stress_Pa, straight.plasma_stress_Pa);
  EXPECT_EQ(read.failure, straight.failure);
  EXPECT_EQ(read.interrupted, straight.interrupted);
}

TEST(ShearedSuspensionResume, ARecordItCannotReadIsBadInputNamingTheFile) {
  ShearedSuspensionRun run;
  run.cell_morphologies = {0};
  run.samples.push_back({0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0, 0});
  const auto good = nlohmann::json::parse(sheared_suspension_record(run).dump());
  const auto expect_refused = [](const nlohmann::json& record, const std::string& what) {
    try {
      sheared_suspension_from_record(record, "rate_000/point.json");
      ADD_FAILURE() << "accepted a record with " << what;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("rate_000/point.json"), std::string::npos)
          << error.what();
    }
  };
  auto missing = good;
  missing.erase("steps");
  expect_refused(missing, "no steps");
  auto short_row = good;
  short_row["samples"][0].erase(7);
  expect_refused(short_row, "a sample of seven numbers");
  auto negative = good;
  negative["samples"][0][6] = -1.0;
  expect_refused(negative, "a negative count");
}

}  // namespace sheared_suspension_resume
}  // namespace rbcsim::cases
