// Checkpoints of the distributed lattice: in the undivided solver's form, so that a run written on
// N processes resumes on M, or in one FluidSolver, bit for bit (tests/parallel/mpi: N -> M under
// mpirun).
#include "common/errors.hpp"
#include "common/state_archive.hpp"
#include "distributed_cases.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace rbcsim::parallel {
namespace {

// An odd count: the AA kernel's swapped layout is what is saved.
constexpr std::size_t kBefore = 13;
constexpr std::size_t kAfter = 12;

testing::DistributedCase channel_with_forces() { return testing::case_named("aa_force_field"); }

TEST(DistributedCheckpoint, IsTheUndividedSolversCheckpoint) {
  const auto flow = channel_with_forces();
  auto fluid = testing::make_distributed(flow, Communicator::self());
  testing::advance_distributed(flow, *fluid, kBefore);
  auto solver = testing::make_undivided(flow);
  testing::advance_undivided(flow, *solver, kBefore);
  StateArchive distributed;
  fluid->save_state(distributed);
  StateArchive undivided;
  solver->save_state(undivided);
  EXPECT_EQ(distributed.arrays(), undivided.arrays());
}

TEST(DistributedCheckpoint, EitherResumesTheOtherBitForBit) {
  const auto flow = channel_with_forces();
  auto uninterrupted = testing::make_undivided(flow);
  testing::advance_undivided(flow, *uninterrupted, kBefore + kAfter);
  const auto expected = uninterrupted->stored_populations(0, uninterrupted->grid().node_count());

  // Distributed -> undivided.
  auto fluid = testing::make_distributed(flow, Communicator::self());
  testing::advance_distributed(flow, *fluid, kBefore);
  StateArchive from_distributed;
  fluid->save_state(from_distributed);
  auto resumed = testing::make_undivided(flow);
  resumed->restore_state(from_distributed);
  testing::advance_undivided(flow, *resumed, kAfter);
  EXPECT_EQ(resumed->stored_populations(0, resumed->grid().node_count()), expected);

  // Undivided -> distributed.
  auto solver = testing::make_undivided(flow);
  testing::advance_undivided(flow, *solver, kBefore);
  StateArchive from_undivided;
  solver->save_state(from_undivided);
  auto restored = testing::make_distributed(flow, Communicator::self());
  restored->restore_state(from_undivided);
  testing::advance_distributed(flow, *restored, kAfter);
  EXPECT_EQ(restored->gather_stored_populations(), expected);
}

TEST(DistributedCheckpoint, AFileOfAnotherLatticeOrConfigIsRefusedNamingIt) {
  const auto flow = channel_with_forces();
  const auto directory = std::filesystem::temp_directory_path() /
                         ("rbcsim_distributed_checkpoint_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  const auto file = directory / "fluid.bin";
  auto fluid = testing::make_distributed(flow, Communicator::self());
  testing::advance_distributed(flow, *fluid, kBefore);
  fluid->write_checkpoint(file, "fingerprint");

  auto same = testing::make_distributed(flow, Communicator::self());
  same->read_checkpoint(file, "fingerprint");
  EXPECT_EQ(same->gather_stored_populations(), fluid->gather_stored_populations());
  EXPECT_EQ(same->local().time(), kBefore);

  EXPECT_THROW(same->read_checkpoint(file, "another config"), InputError);
  DistributedFluid larger(
      Communicator::self(),
      lattice::LatticeGrid(testing::kCaseNx, testing::kCaseNy, 2 * testing::kCaseNz), 2,
      flow.parameters);
  try {
    larger.read_checkpoint(file, "fingerprint");
    FAIL() << "a checkpoint of another lattice was read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("fluid."), std::string::npos) << error.what();
  }
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace rbcsim::parallel
