// Checkpoint and resume of the coupled loop (docs/architecture.md): N steps straight and N/2 +
// checkpoint + a new simulation resumed for N/2 give bit-identical positions and populations, with
// 1 and 2 threads, also with a cytoplasm viscosity contrast (whose indicator is recomputed from the
// positions, not saved) and with membrane viscosity (whose implicit step, every second step of the
// optimised fluid kernel, must resume in phase); a checkpoint of another setup, config or a damaged file is refused with
// one line; an interrupted run writes a checkpoint.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "common/thread_count_scope.hpp"
#include "coupling/checkpoint.hpp"
#include "coupling/coupling_fixtures.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::coupling {
namespace {

using rbcsim::testing::ScratchDirectory;
using testing::plasma_units;
using testing::sphere_mesh;
using testing::stretched;

// Half of it odd: the optimised fluid kernel then holds its populations post-collision in the
// swapped (AA) layout, which the checkpoint must restore as is to resume bit for bit.
constexpr std::size_t kSteps = 26;
constexpr const char* kFingerprint = "config sha256 of the test";

// A deformed capsule in a Lees-Edwards shear flow (the fluid's step count moves the sliding
// images, so it must be restored too), advanced with AB2 (a velocity history), stopped by time
// with two criteria that remember something. A viscosity ratio other than 1 makes the interior
// more viscous.
std::unique_ptr<CoupledSimulation> sheared_capsule(int nx = 20, double viscosity_ratio = 1.0,
                                                   bool membrane_viscosity = false) {
  lattice::FluidParameters fluid_parameters;
  fluid_parameters.lees_edwards_velocity = 0.02;
  fluid_parameters.inner_viscosity_ratio = viscosity_ratio;
  auto fluid =
      std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(nx, 18, 16), fluid_parameters);
  CouplingParameters parameters;
  parameters.point_advance = "ab2";
  auto simulation =
      std::make_unique<CoupledSimulation>(std::move(fluid), plasma_units(), parameters);
  const Vec3 centre_um(4.7, 4.3, 3.9);
  const auto sphere = sphere_mesh(2, 2.0, centre_um);
  membrane::MembraneParameters membrane;
  if (membrane_viscosity) membrane.forces.push_back("viscosity");
  simulation->add_cell(membrane::MembraneModel(sphere, membrane),
                       stretched(sphere, centre_um, Vec3(1.1, 0.95, 1.0)));
  const double dt_s = simulation->units().to_physical(units::PhysicalUnit::time_s, 1.0);
  simulation->add_stop_criterion(stop_at_time(static_cast<double>(kSteps) * dt_s));
  simulation->add_stop_criterion(stop_after_distance(*simulation, 0, 100.0));
  simulation->add_stop_criterion(stop_at_steady_state(
      "x centroid", [](const CoupledSimulation& s) { return s.cell(0).centroid_lu().x(); },
      {.relative_rate_per_s = 1e-12, .check_interval_s = 3.0 * dt_s}));
  return simulation;
}

struct FinalState {
  std::vector<Vec3> positions_lu;
  std::vector<double> populations;
  std::size_t time_step;
};

FinalState final_state(const CoupledSimulation& simulation) {
  const auto positions = simulation.cell(0).positions_lu();
  return {{positions.begin(), positions.end()},
          simulation.fluid().pre_collision_populations(),
          simulation.time_step()};
}

void expect_identical(const FinalState& straight, const FinalState& resumed) {
  EXPECT_EQ(straight.time_step, resumed.time_step);
  ASSERT_EQ(straight.positions_lu.size(), resumed.positions_lu.size());
  for (std::size_t v = 0; v < straight.positions_lu.size(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(straight.positions_lu[v][axis], resumed.positions_lu[v][axis]) << "vertex " << v;
    }
  }
  EXPECT_TRUE(straight.populations == resumed.populations);
}

// Runs kSteps straight with a checkpoint every kSteps / 2 (so the file holds step kSteps / 2),
// then resumes a new simulation from it with `resume_threads` and runs it to kSteps.
void check_resume(int straight_threads, int resume_threads, double viscosity_ratio = 1.0,
                  bool membrane_viscosity = false) {
  const ScratchDirectory scratch;
  const auto file = scratch.path() / kCheckpointFileName;
  FinalState straight;
  {
    const ThreadCountScope threads(straight_threads);
    auto simulation = sheared_capsule(20, viscosity_ratio, membrane_viscosity);
    simulation->set_checkpoint_policy({file, kFingerprint, kSteps / 2, 0.0});
    EXPECT_EQ(simulation->run().stop_reason.rfind("reached the time limit", 0), 0u);
    straight = final_state(*simulation);
  }
  const ThreadCountScope threads(resume_threads);
  auto resumed = sheared_capsule(20, viscosity_ratio, membrane_viscosity);
  resumed->set_checkpoint_policy({file, kFingerprint, 0, 0.0});
  resumed->resume_from(file);
  EXPECT_EQ(resumed->time_step(), kSteps / 2);
  EXPECT_EQ(resumed->run().steps, kSteps / 2);
  expect_identical(straight, final_state(*resumed));
  // The run moved something: a resume that skipped the fluid would not match by chance.
  EXPECT_NE(straight.positions_lu[0], sheared_capsule()->cell(0).positions_lu()[0]);
}

TEST(Checkpoint, ResumedRunIsBitIdenticalWithOneThread) { check_resume(1, 1); }

TEST(Checkpoint, ResumedRunIsBitIdenticalWithTwoThreadsAndAcrossThreadCounts) {
  check_resume(2, 2);
  check_resume(1, 2);
}

TEST(Checkpoint, ResumedRunWithACytoplasmViscosityContrastIsBitIdentical) {
  check_resume(1, 1, 5.0);
  check_resume(2, 1, 5.0);
}

TEST(Checkpoint, ResumedRunWithMembraneViscosityIsBitIdentical) {
  check_resume(1, 1, 1.0, true);
  check_resume(2, 1, 1.0, true);
}

class CheckpointRefused : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = scratch_.path() / kCheckpointFileName;
    auto simulation = sheared_capsule();
    simulation->step();
    write_checkpoint(file_, *simulation, kFingerprint);
  }

  void expect_refused(CoupledSimulation& simulation, const std::string& problem,
                      const char* fingerprint = kFingerprint) const {
    try {
      read_checkpoint(file_, simulation, fingerprint);
      ADD_FAILURE() << "accepted; expected: " << problem;
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(file_.string() + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(problem), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }

  void damage(std::size_t offset_from_end, bool truncate) const {
    auto bytes = rbcsim::testing::read_text(file_);
    if (truncate) {
      bytes.resize(bytes.size() - offset_from_end);
    } else {
      bytes[bytes.size() - offset_from_end] ^= 0x20;
    }
    std::ofstream(file_, std::ios::binary | std::ios::trunc) << bytes;
  }

  ScratchDirectory scratch_;
  std::filesystem::path file_;
};

TEST_F(CheckpointRefused, AnotherGrid) {
  expect_refused(*sheared_capsule(22),
                 "'fluid.populations' has 109440 values, this simulation needs 120384");
}

TEST_F(CheckpointRefused, AnotherConfig) {
  expect_refused(*sheared_capsule(), "written by a run with a different config", "other");
}

TEST_F(CheckpointRefused, SimulationWithMoreCells) {
  auto two_cells = sheared_capsule();
  const auto small = sphere_mesh(1, 1.0, Vec3(8.3, 6.5, 4.0));
  two_cells->add_cell(membrane::MembraneModel(small, membrane::MembraneParameters{}),
                      small.positions_um);
  expect_refused(*two_cells, "no 'cell 1.positions_lu' in it");
}

TEST_F(CheckpointRefused, FlippedBit) {
  damage(1000, false);
  expect_refused(*sheared_capsule(), "the SHA-256 checksum does not match");
}

TEST_F(CheckpointRefused, Truncated) {
  damage(100, true);
  expect_refused(*sheared_capsule(), "checksum does not match");
}

TEST_F(CheckpointRefused, NotACheckpoint) {
  std::ofstream(file_, std::ios::trunc) << "{\"status\": \"ok\"}\n";
  expect_refused(*sheared_capsule(), "not an rbcsim checkpoint");
}

TEST(Checkpoint, InterruptedRunWritesACheckpointAndTheFinalObservation) {
  const ScratchDirectory scratch;
  const auto file = scratch.path() / kCheckpointFileName;
  auto simulation = sheared_capsule();
  simulation->set_checkpoint_policy({file, kFingerprint, 0, 0.0});
  std::vector<std::size_t> observed_steps;
  simulation->add_observer({"steps", 5, [&](const CoupledSimulation& s) {
                              observed_steps.push_back(s.time_step());
                              if (s.time_step() == 5) request_interrupt(SIGINT);
                            }});
  EXPECT_THROW(simulation->run(), Interrupted);
  clear_interrupt();
  EXPECT_EQ(observed_steps, (std::vector<std::size_t>{0, 5}));
  auto resumed = sheared_capsule();
  resumed->set_checkpoint_policy({file, kFingerprint, 0, 0.0});
  resumed->resume_from(file);
  EXPECT_EQ(resumed->time_step(), 5u);
}

}  // namespace
}  // namespace rbcsim::coupling
