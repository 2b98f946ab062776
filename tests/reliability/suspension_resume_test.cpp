// Checkpoint and resume of a suspension (cases/suspension_case.hpp): a run interrupted after
// kInterruptStep steps, between two sample intervals, then resumed from its checkpoint, ends with
// the straight run's samples, cell samples and counts bit for bit. Through the binary:
// tests/cli_capillary/cli_suspension_test.cpp. (A named namespace: the unity build merges this
// file with capillary_resume_test.cpp.)
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cases/suspension_case.hpp"
#include "common/interrupt.hpp"
#include "config/config.hpp"
#include "coupling/checkpoint.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/suspension_from_config.hpp"
#include "support/expect_each.hpp"
#include "support/interrupt_scope.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::cases {
namespace suspension_resume {

using rbcsim::testing::expect_each_same;
using rbcsim::testing::interrupt_after_step;
using rbcsim::testing::InterruptScope;
using rbcsim::testing::resume_from_checkpoint;
using rbcsim::testing::ScratchDirectory;

constexpr std::size_t kTotalSteps = 30;
constexpr std::size_t kSampleSteps = 4;
// Odd (the optimised kernel's swapped layout) and not a multiple of kSampleSteps.
constexpr std::size_t kInterruptStep = 13;

// Two coarse cells (162 vertices, dx = 1 um) in a 10 um tube, of two morphologies.
const std::vector<std::string> kCoarse = {"mesh.subdivisions=2",
                                          "mesh.method=parametric",
                                          "lattice.spacing_um=1",
                                          "suspension.contact_range_um=1.75",
                                          "suspension.tube_diameter_um=10",
                                          "suspension.tube_length_um=12",
                                          "suspension.hematocrit=0.2",
                                          "suspension.mix=discocyte=0.5,stomatocyte-II=0.5"};

class CoarseSuspension {
 public:
  CoarseSuspension()
      : request_{.assignments = kCoarse},
        config_(config::resolve_config(request_)),
        mix_(setup::suspension_mix_from(config_)),
        morphologies_(setup::suspension_morphologies_from(request_, mix_, 1.0)) {}

  SuspensionRun run(const SuspensionConfigure& configure) const {
    const SuspensionPhysics physics{setup::fluid_parameters_from(config_),
                                    setup::coupling_parameters_from(config_, {}),
                                    config::make_unit_converter(config_)};
    auto settings = setup::suspension_settings_from(config_);
    const double dt_s = physics.units.dt_s();
    settings.duration_s = (static_cast<double>(kTotalSteps) - 0.5) * dt_s;
    settings.sample_interval_s = static_cast<double>(kSampleSteps) * dt_s;
    const std::vector<std::size_t> cells{0, 1};
    return run_suspension(morphologies_, cells, physics, settings, configure);
  }

 private:
  config::ConfigRequest request_;
  config::Config config_;
  setup::SuspensionMix mix_;
  std::vector<SuspensionMorphology> morphologies_;
};

void expect_same(const SuspensionSample& resumed, const SuspensionSample& straight) {
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.flow_rate_um3_per_s, straight.flow_rate_um3_per_s);
  EXPECT_EQ(resumed.relative_apparent_viscosity, straight.relative_apparent_viscosity);
  EXPECT_EQ(resumed.tube_hematocrit, straight.tube_hematocrit);
  EXPECT_EQ(resumed.discharge_hematocrit, straight.discharge_hematocrit);
  EXPECT_EQ(resumed.cell_free_layer_um, straight.cell_free_layer_um);
  EXPECT_EQ(resumed.populated_bin_fraction, straight.populated_bin_fraction);
  EXPECT_EQ(resumed.contact_pairs, straight.contact_pairs);
  EXPECT_EQ(resumed.close_contact_pairs, straight.close_contact_pairs);
  EXPECT_EQ(resumed.pierced_cells, straight.pierced_cells);
  EXPECT_EQ(resumed.volume_fraction_by_ring, straight.volume_fraction_by_ring);
}

void expect_same(const SuspensionCellSample& resumed, const SuspensionCellSample& straight) {
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.cell, straight.cell);
  EXPECT_EQ(resumed.centroid_um, straight.centroid_um);
  EXPECT_EQ(resumed.radial_position_um, straight.radial_position_um);
  EXPECT_EQ(resumed.velocity_x_m_per_s, straight.velocity_x_m_per_s);
  EXPECT_EQ(resumed.deformation_index, straight.deformation_index);
}

TEST(SuspensionResume, InterruptedThenResumedRunEndsAsAStraightRun) {
  const InterruptScope scope;
  const CoarseSuspension suspension;
  const auto straight = suspension.run({});
  ASSERT_TRUE(straight.ok()) << straight.failure;
  ASSERT_EQ(straight.steps, kTotalSteps) << straight.stop_reason;
  // Every kSampleSteps from step 0, and the final state (step 30).
  ASSERT_EQ(straight.samples.size(), kTotalSteps / kSampleSteps + 2);

  const ScratchDirectory scratch;
  const auto file = scratch.path() / coupling::kCheckpointFileName;
  const auto interrupted =
      suspension.run(interrupt_after_step(kInterruptStep, file, "suspension resume test"));
  ASSERT_TRUE(interrupted.interrupted) << interrupted.failure;
  EXPECT_EQ(interrupted.steps, kInterruptStep);
  // The results so far include the state reached, between two sample intervals.
  ASSERT_EQ(interrupted.samples.size(), kInterruptStep / kSampleSteps + 2);
  EXPECT_EQ(interrupted.samples.back().time_s, interrupted.time_s);
  EXPECT_EQ(interrupted.cell_samples.size(), 2 * interrupted.samples.size());
  ASSERT_TRUE(std::filesystem::exists(file));
  clear_interrupt();

  const auto resumed = suspension.run(resume_from_checkpoint(file, "suspension resume test"));
  ASSERT_TRUE(resumed.ok()) << resumed.failure;
  EXPECT_EQ(resumed.steps, straight.steps);
  EXPECT_EQ(resumed.time_s, straight.time_s);
  EXPECT_EQ(resumed.stop_reason, straight.stop_reason);
  EXPECT_EQ(resumed.close_contact_steps, straight.close_contact_steps);
  EXPECT_EQ(resumed.capped_contact_steps, straight.capped_contact_steps);
  EXPECT_EQ(resumed.samples_with_pierced_cells, straight.samples_with_pierced_cells);
  EXPECT_EQ(resumed.force_capped_steps, straight.force_capped_steps);
  const auto same = [](const auto& a, const auto& b) { expect_same(a, b); };
  expect_each_same(resumed.samples, straight.samples, same);
  expect_each_same(resumed.cell_samples, straight.cell_samples, same);
  EXPECT_EQ(resumed.averages.relative_apparent_viscosity,
            straight.averages.relative_apparent_viscosity);
}

}  // namespace suspension_resume
}  // namespace rbcsim::cases
