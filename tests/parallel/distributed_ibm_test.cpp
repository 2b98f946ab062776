// The immersed boundary on the distributed lattice against the undivided one (ibm/transfer.hpp),
// on one process (tests/parallel/mpi: 1-4 processes): points spread, the fluid stepped, the points
// moved by their interpolated velocities across block boundaries and the periodic seam.
#include "parallel/distributed_ibm.hpp"
#include "distributed_cases.hpp"
#include "ibm/delta_kernels.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace rbcsim::parallel {
namespace {

class OneProcessCoupled : public ::testing::TestWithParam<std::string> {};

TEST_P(OneProcessCoupled, PointsAndFluidMoveAsOnTheUndividedLatticeBitForBit) {
  constexpr std::size_t kSteps = 30;
  const auto undivided = testing::run_coupled_undivided(GetParam(), kSteps);
  const auto distributed =
      testing::run_coupled_distributed(GetParam(), kSteps, Communicator::self());
  EXPECT_EQ(distributed.positions, undivided.positions);
  EXPECT_EQ(distributed.populations, undivided.populations);
  // The points did move: a test of nothing would pass too.
  const auto still = testing::run_coupled_undivided(GetParam(), 0);
  EXPECT_NE(undivided.positions, still.positions);
}

INSTANTIATE_TEST_SUITE_P(DistributedImmersedBoundary, OneProcessCoupled,
                         ::testing::Values("phi2", "phi3", "phi4"),
                         [](const auto& parameter) { return parameter.param; });

TEST(DistributedImmersedBoundary, EveryKernelOfTheTableFitsTheGhostPlanes) {
  // A kernel wider than 4 nodes would need more ghost planes and is refused; none of ours is.
  DistributedFluid fluid(Communicator::self(), lattice::LatticeGrid(4, 4, 8), 2,
                         lattice::FluidParameters{});
  for (const auto& kernel : ibm::delta_kernels()) {
    EXPECT_NO_THROW(DistributedImmersedBoundary(fluid, kernel.name)) << kernel.name;
  }
}

}  // namespace
}  // namespace rbcsim::parallel
