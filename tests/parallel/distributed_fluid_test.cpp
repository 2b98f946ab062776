// The fluid on the distributed lattice against the same fluid on one undivided FluidSolver, on one
// process (tests/parallel/mpi runs the same cases on 1-4 processes under mpirun).
#include "parallel/distributed_fluid.hpp"
#include "common/errors.hpp"
#include "distributed_cases.hpp"
#include "lattice/d3q19.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rbcsim::parallel {
namespace {

class OneProcess : public ::testing::TestWithParam<testing::DistributedCase> {};

// Bit for bit: every node of the slab computes what the undivided solver's node computes. A halo
// one plane thin, a ghost plane left stale, or the exchange after the step instead of before
// breaks this within a few steps.
TEST_P(OneProcess, SlabWithGhostPlanesIsTheUndividedLatticeBitForBit) {
  const auto undivided = testing::run_undivided(GetParam());
  const auto distributed = testing::run_distributed(GetParam(), Communicator::self());
  ASSERT_EQ(distributed.size(), undivided.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < undivided.size(); ++k) {
    if (distributed[k] != undivided[k]) ++differing;
  }
  EXPECT_EQ(differing, 0u) << "of " << undivided.size() << " stored populations";
}

INSTANTIATE_TEST_SUITE_P(DistributedFluid, OneProcess,
                         ::testing::ValuesIn(testing::distributed_cases()),
                         [](const auto& parameter) { return parameter.param.name; });

TEST(DistributedFluid, TheFullStateHaloSendsTwoPlanesEachWayEveryStep) {
  DistributedFluid fluid(Communicator::self(), lattice::LatticeGrid(5, 4, 8), 4,
                         lattice::FluidParameters{}, {}, HaloScheme::full_state);
  fluid.initialise_equilibrium(1.0, {0.0, 0.0, 0.0});
  fluid.advance(3);
  const auto& counters = fluid.halo_counters();
  EXPECT_EQ(counters.exchanges, 3u);
  EXPECT_EQ(counters.messages, 6u);
  EXPECT_EQ(counters.bytes, 3u * 2u * (2u * 5u * 4u) * lattice::kDirections * sizeof(double));
}

TEST(DistributedFluid, TheAaKernelsHaloSendsFiveCrossingPopulationsOfOnePlaneAtItsStreamingStep) {
  DistributedFluid fluid(Communicator::self(), lattice::LatticeGrid(5, 4, 8), 4,
                         lattice::FluidParameters{});
  ASSERT_EQ(fluid.halo_scheme(), HaloScheme::crossing_populations);
  fluid.initialise_equilibrium(1.0, {0.0, 0.0, 0.0});
  fluid.advance(3);  // local, streaming (exchanges before and after), local
  const auto& counters = fluid.halo_counters();
  EXPECT_EQ(counters.exchanges, 2u);
  EXPECT_EQ(counters.messages, 4u);
  EXPECT_EQ(counters.bytes, 2u * 2u * (5u * 4u) * 5u * sizeof(double));
}

TEST(DistributedFluid, TheCrossingHaloNeedsTheAaKernelAndNoSlidingPlane) {
  lattice::FluidParameters reference;
  reference.kernel = "reference";
  EXPECT_THROW(DistributedFluid(Communicator::self(), lattice::LatticeGrid(3, 3, 4), 2, reference,
                                {}, HaloScheme::crossing_populations),
               std::logic_error);
  lattice::FluidParameters sheared;
  sheared.lees_edwards_velocity = 0.01;
  EXPECT_THROW(DistributedFluid(Communicator::self(), lattice::LatticeGrid(3, 3, 4), 2, sheared, {},
                                HaloScheme::crossing_populations),
               std::logic_error);
  EXPECT_EQ(DistributedFluid(Communicator::self(), lattice::LatticeGrid(3, 3, 4), 2, sheared)
                .halo_scheme(),
            HaloScheme::full_state);
}

TEST(DistributedFluid, MassOfAClosedChannelIsKept) {
  lattice::FluidParameters parameters;
  parameters.body_force = {1e-4, 0.0, 0.0};
  DistributedFluid fluid(Communicator::self(), lattice::LatticeGrid(4, 6, 6), 2, parameters,
                         [](int, int y, int) { return y == 0 || y == 5; });
  fluid.initialise_equilibrium(1.0, {0.0, 0.0, 0.0});
  const double fluid_nodes = 4.0 * 4.0 * 6.0;
  EXPECT_NEAR(fluid.total_mass(), fluid_nodes, 1e-12 * fluid_nodes);
  fluid.advance(40);
  EXPECT_NEAR(fluid.total_mass(), fluid_nodes, 1e-11 * fluid_nodes);
}

TEST(DistributedFluid, ANonFiniteVelocityStopsTheRunNamingTheGlobalNode) {
  DistributedFluid fluid(Communicator::self(), lattice::LatticeGrid(3, 3, 4), 2,
                         lattice::FluidParameters{});
  fluid.initialise_equilibrium(1.0, {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0});
  try {
    fluid.require_finite_velocity();
    FAIL() << "a NaN velocity passed";
  } catch (const RuntimeFailure& failure) {
    EXPECT_NE(std::string(failure.what()).find("node (0, 0, 0)"), std::string::npos)
        << failure.what();
  }
}

// Cut from an undivided solver a case set up (CoupledSimulation across processes): its walls,
// parameters and state after some steps, then stepped on as the undivided one, bit for bit.
TEST(DistributedFluid, CutFromAnUndividedSolverStepsOnAsIt) {
  const testing::DistributedCase flow = testing::case_named("aa_obstacle_across_slabs");
  auto whole = testing::make_undivided(flow);
  testing::advance_undivided(flow, *whole, 7);
  DistributedFluid cut(Communicator::self(), *whole, 2);
  EXPECT_EQ(cut.decomposition().block_count(), testing::kCaseNz / 2);
  testing::advance_distributed(flow, cut, 8);
  testing::advance_undivided(flow, *whole, 8);
  EXPECT_EQ(cut.gather_stored_populations(),
            whole->stored_populations(0, whole->grid().node_count()));
}

// The tube flow of testing::make_tube_channel (inlet, outlet, resting and moving walls, wall
// links) cut into slabs: with the AA kernel's crossing populations and, with the reference kernel,
// the full state, half-way; and with curved walls (Bouzidi), whose links read the node behind on
// the next plane, the full-state halo. Stepped on as the undivided solver, bit for bit.
struct CutCase {
  std::string kernel;
  std::string wall_rule;
  HaloScheme scheme;
};

class CutChannel : public ::testing::TestWithParam<CutCase> {};

TEST_P(CutChannel, InletOutletAndMovingWallsStepOnAsTheUndividedSolver) {
  const CutCase& cut_case = GetParam();
  auto whole = testing::make_tube_channel(cut_case.kernel, cut_case.wall_rule, 5);
  DistributedFluid cut(Communicator::self(), *whole, 2);
  EXPECT_EQ(cut.halo_scheme(), cut_case.scheme);
  cut.advance(21);
  whole->advance(21);
  const std::size_t nodes = whole->grid().node_count();
  const auto cut_state = testing::at_fluid_nodes(*whole, cut.gather_stored_populations());
  const auto whole_state = testing::at_fluid_nodes(*whole, whole->stored_populations(0, nodes));
  ASSERT_EQ(cut_state.size(), whole_state.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < whole_state.size(); ++k) {
    if (cut_state[k] != whole_state[k]) ++differing;
  }
  EXPECT_EQ(differing, 0u) << "of " << whole_state.size() << " populations at fluid nodes";
}

INSTANTIATE_TEST_SUITE_P(
    DistributedFluid, CutChannel,
    ::testing::Values(CutCase{"optimised", "halfway", HaloScheme::crossing_populations},
                      CutCase{"reference", "halfway", HaloScheme::full_state},
                      CutCase{"optimised", "bouzidi", HaloScheme::full_state},
                      CutCase{"reference", "bouzidi", HaloScheme::full_state}),
    [](const auto& parameter) { return parameter.param.kernel + "_" + parameter.param.wall_rule; });

// The curved walls' links are what makes the difference: without them, Bouzidi's channel is the
// half-way one (so the test above would pass with the links lost in the cut).
TEST(DistributedFluid, CurvedWallLinksChangeTheTubeChannel) {
  auto curved = testing::make_tube_channel("optimised", "bouzidi", 26);
  auto halfway = testing::make_tube_channel("optimised", "halfway", 26);
  const std::size_t nodes = curved->grid().node_count();
  EXPECT_NE(curved->stored_populations(0, nodes), halfway->stored_populations(0, nodes));
}

}  // namespace
}  // namespace rbcsim::parallel
