// The equality cases of tests/parallel on every process of an MPI run: ctest starts this under
// `mpiexec -n 1/2/3/4` (label `mpi`). Rank 0 compares the gathered state of the distributed lattice
// with the undivided solver's, bit for bit: so the state is the same on any number of processes;
// and a checkpoint written on all of them resumes on fewer.
// Only rank 0 prints; the exit code is 1 if any rank failed a test.
#include "distributed_cases.hpp"
#include "parallel/communicator.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace rbcsim::parallel {
namespace {

class Processes : public ::testing::TestWithParam<testing::DistributedCase> {};

TEST_P(Processes, DistributedStateIsTheUndividedLatticesBitForBit) {
  const Communicator world = Communicator::world();
  ASSERT_TRUE(MpiSession::active() || world.size() == 1);
  const auto distributed = testing::run_distributed(GetParam(), world);
  if (!world.is_root()) return;
  const auto undivided = testing::run_undivided(GetParam());
  ASSERT_EQ(distributed.size(), undivided.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < undivided.size(); ++k) {
    if (distributed[k] != undivided[k]) ++differing;
  }
  EXPECT_EQ(differing, 0u) << "of " << undivided.size() << " stored populations on " << world.size()
                           << " processes";
}

INSTANTIATE_TEST_SUITE_P(DistributedFluid, Processes,
                         ::testing::ValuesIn(testing::distributed_cases()),
                         [](const auto& parameter) { return parameter.param.name; });

// The tube channel with curved walls (Bouzidi links, some across z: the node behind on another
// process's plane) cut from the undivided solver: the full-state halo, the same state on any
// number of processes.
TEST(ProcessesCurvedWalls, TubeChannelStepsOnAsTheUndividedSolverBitForBit) {
  const Communicator world = Communicator::world();
  for (const std::string kernel : {"optimised", "reference"}) {
    auto whole = testing::make_tube_channel(kernel, "bouzidi", 5);
    DistributedFluid cut(world, *whole, 2);
    EXPECT_EQ(cut.halo_scheme(), HaloScheme::full_state);
    cut.advance(21);
    const auto gathered = cut.gather_stored_populations();
    if (!world.is_root()) continue;
    whole->advance(21);
    const std::size_t nodes = whole->grid().node_count();
    EXPECT_EQ(testing::at_fluid_nodes(*whole, gathered),
              testing::at_fluid_nodes(*whole, whole->stored_populations(0, nodes)))
        << kernel << " kernel on " << world.size() << " processes";
  }
}

// Points spread and moved across block boundaries and the periodic seam: on any number of
// processes as on the undivided lattice.
class ProcessesCoupled : public ::testing::TestWithParam<std::string> {};

TEST_P(ProcessesCoupled, PointsAndFluidMoveAsOnTheUndividedLatticeBitForBit) {
  constexpr std::size_t kSteps = 30;
  const Communicator world = Communicator::world();
  const auto distributed = testing::run_coupled_distributed(GetParam(), kSteps, world);
  if (!world.is_root()) return;
  const auto undivided = testing::run_coupled_undivided(GetParam(), kSteps);
  EXPECT_EQ(distributed.positions, undivided.positions) << "on " << world.size() << " processes";
  EXPECT_EQ(distributed.populations, undivided.populations)
      << "on " << world.size() << " processes";
}

INSTANTIATE_TEST_SUITE_P(DistributedImmersedBoundary, ProcessesCoupled,
                         ::testing::Values("phi2", "phi3", "phi4"),
                         [](const auto& parameter) { return parameter.param; });

// Written on every process of the run, resumed on the first half of them (4 -> 2, 3 -> 2, 2 -> 1)
// and on rank 0 alone: the uninterrupted undivided run's state, bit for bit.
TEST(ProcessesCheckpoint, WrittenOnAllResumesOnFewerProcessesBitForBit) {
  constexpr std::size_t kBefore = 13;
  constexpr std::size_t kAfter = 12;
  const testing::DistributedCase flow = testing::case_named("aa_force_field");
  const Communicator world = Communicator::world();
  const auto file = testing::checkpoint_file(world, "rbcsim_mpi_checkpoint_");
  auto fluid = testing::make_distributed(flow, world);
  testing::advance_distributed(flow, *fluid, kBefore);
  fluid->write_checkpoint(file, "mpi test");

  std::vector<double> expected;
  if (world.is_root()) {
    auto uninterrupted = testing::make_undivided(flow);
    testing::advance_undivided(flow, *uninterrupted, kBefore + kAfter);
    expected = uninterrupted->stored_populations(0, uninterrupted->grid().node_count());
  }
  const int half = (world.size() + 1) / 2;
  const Communicator part = world.split(world.rank() < half ? 0 : 1);
  if (world.rank() < half) {
    auto resumed = testing::make_distributed(flow, part);
    resumed->read_checkpoint(file, "mpi test");
    testing::advance_distributed(flow, *resumed, kAfter);
    const auto state = resumed->gather_stored_populations();
    if (world.is_root()) {
      EXPECT_EQ(state, expected) << "written on " << world.size() << ", resumed on " << half;
    }
  }
  if (world.is_root()) {
    auto alone = testing::make_distributed(flow, Communicator::self());
    alone->read_checkpoint(file, "mpi test");
    testing::advance_distributed(flow, *alone, kAfter);
    EXPECT_EQ(alone->gather_stored_populations(), expected) << "resumed on one process";
  }
  world.barrier();
  if (world.is_root()) std::filesystem::remove(file);
}

// Written on rank 0 alone, resumed on every process of the run.
TEST(ProcessesCheckpoint, WrittenOnOneResumesOnAllBitForBit) {
  constexpr std::size_t kBefore = 13;
  constexpr std::size_t kAfter = 12;
  const testing::DistributedCase flow = testing::case_named("aa_obstacle_across_slabs");
  const Communicator world = Communicator::world();
  const auto file = testing::checkpoint_file(world, "rbcsim_mpi_checkpoint_one_");
  std::vector<double> expected;
  if (world.is_root()) {
    auto alone = testing::make_distributed(flow, Communicator::self());
    testing::advance_distributed(flow, *alone, kBefore);
    alone->write_checkpoint(file, "mpi test");
    auto uninterrupted = testing::make_undivided(flow);
    testing::advance_undivided(flow, *uninterrupted, kBefore + kAfter);
    expected = uninterrupted->stored_populations(0, uninterrupted->grid().node_count());
  }
  world.barrier();
  auto resumed = testing::make_distributed(flow, world);
  resumed->read_checkpoint(file, "mpi test");
  testing::advance_distributed(flow, *resumed, kAfter);
  const auto state = resumed->gather_stored_populations();
  if (world.is_root()) {
    EXPECT_EQ(state, expected) << "written on one, resumed on " << world.size();
    std::filesystem::remove(file);
  }
}

// A channel driven by a body force from rest to its steady state (the capillary's and the tube
// suspension's set-up), with an obstacle in two planes so that each slab's flow is its own (a
// slab deciding on its own measure stops at another step), in slabs: the same number of steps, the
// same measure and the same state, bit for bit, on every process, as the undivided solver's
// run_to_steady_state.
TEST(ProcessesSteadyState, AChannelSettlesAsTheUndividedSolverBitForBit) {
  const lattice::LatticeGrid grid(5, 9, 8);
  const auto channel = [&grid] {
    lattice::FluidParameters parameters;
    parameters.body_force = {2e-6, 0.0, 0.0};
    auto solver = std::make_unique<lattice::FluidSolver>(grid, parameters);
    for (int z = 0; z < grid.nz(); ++z) {
      for (int x = 0; x < grid.nx(); ++x) {
        solver->set_wall(grid.index(x, 0, z));
        solver->set_wall(grid.index(x, grid.ny() - 1, z));
      }
    }
    for (int z = 2; z < 4; ++z) {
      for (int y = 3; y < 6; ++y) solver->set_wall(grid.index(2, y, z));
    }
    return solver;
  };
  const lattice::SteadyStateCriterion criterion{1e-8, 20, 20000};
  const Communicator world = Communicator::world();
  auto settled = channel();
  const auto result = run_to_steady_state(world, *settled, 2, criterion);
  auto alone = channel();
  const auto expected = alone->run_to_steady_state(criterion);
  ASSERT_TRUE(expected.converged);
  // Many checks, not a flow steady at the first: the slabs measure and agree again and again.
  EXPECT_GT(expected.steps, 10 * criterion.check_interval) << expected.steps;
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.steps, expected.steps) << "on " << world.size() << " processes";
  EXPECT_EQ(result.relative_velocity_change, expected.relative_velocity_change);
  EXPECT_EQ(settled->stored_populations(0, grid.node_count()),
            alone->stored_populations(0, grid.node_count()))
      << "process " << world.rank() << " of " << world.size();
  EXPECT_EQ(settled->time(), alone->time());
}

}  // namespace
}  // namespace rbcsim::parallel

int main(int argc, char** argv) {
  rbcsim::parallel::MpiSession session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  const auto world = rbcsim::parallel::Communicator::world();
  if (!world.is_root()) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int result = RUN_ALL_TESTS();
  return world.any(result != 0) ? 1 : 0;
}
