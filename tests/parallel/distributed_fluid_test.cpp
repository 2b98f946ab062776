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

// A tube flow as the capillary sets it up: a velocity inlet (a moving wall) at x = 0 with a
// profile, a pressure outlet at x = nx - 1, resting walls at y = 0 and y = ny - 1, half-way wall
// links. Cut into slabs (both halo schemes: the AA kernel's crossing populations and, with the
// reference kernel, the full state) it steps on as the undivided solver, bit for bit.
class CutChannel : public ::testing::TestWithParam<std::string> {};

TEST_P(CutChannel, InletOutletAndMovingWallsStepOnAsTheUndividedSolver) {
  const lattice::LatticeGrid grid(8, 6, 12);
  lattice::FluidParameters parameters;
  parameters.kernel = GetParam();
  lattice::FluidSolver whole(grid, parameters);
  std::vector<lattice::WallLink> links;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) {
      whole.set_wall(grid.index(x, 0, z));
      whole.set_wall(grid.index(x, grid.ny() - 1, z), {0.004, 0.0, 0.001});
      links.push_back({grid.index(x, 1, z), 4, 0.3});  // c = (0, -1, 0): towards y = 0
    }
    for (int y = 1; y < grid.ny() - 1; ++y) {
      whole.set_velocity_inlet(grid.index(0, y, z),
                               {0.01 * y * (grid.ny() - 1 - y) / 4.0, 0.0, 0.0});
      whole.set_pressure_outlet(grid.index(grid.nx() - 1, y, z), 1.0);
    }
  }
  ASSERT_GT(whole.set_wall_links(links), 0u);
  whole.initialise_equilibrium(1.0, {0.005, 0.0, 0.0});
  whole.advance(5);
  DistributedFluid cut(Communicator::self(), whole, 2);
  EXPECT_EQ(cut.halo_scheme(),
            GetParam() == "optimised" ? HaloScheme::crossing_populations : HaloScheme::full_state);
  cut.advance(21);
  whole.advance(21);
  // At the fluid nodes: a solid node's populations are never read (every rule takes the fluid
  // node's own), and the reference kernel's second buffer keeps there what the solver was built
  // with, which a restored state (the cut's start) does not carry.
  const auto cut_state = cut.gather_stored_populations();
  const auto whole_state = whole.stored_populations(0, grid.node_count());
  ASSERT_EQ(cut_state.size(), whole_state.size());
  std::size_t compared = 0;
  std::size_t differing = 0;
  for (std::size_t k = 0; k < whole_state.size(); ++k) {
    if (!whole.boundaries().is_fluid(k % grid.node_count())) continue;
    ++compared;
    if (cut_state[k] != whole_state[k]) ++differing;
  }
  EXPECT_EQ(differing, 0u) << "of " << compared << " populations at fluid nodes";
}

INSTANTIATE_TEST_SUITE_P(DistributedFluid, CutChannel, ::testing::Values("optimised", "reference"));

// Interpolated wall links read the node behind, which a slab's edge may not hold exactly: named,
// not run wrong.
TEST(DistributedFluid, CutFromAnUndividedSolverRefusesInterpolatedWallLinks) {
  const lattice::LatticeGrid grid(4, 4, 4);
  lattice::FluidParameters parameters;
  parameters.wall_rule = "bouzidi";
  lattice::FluidSolver whole(grid, parameters);
  whole.set_wall(grid.index(0, 0, 0));
  ASSERT_EQ(whole.set_wall_links(std::vector<lattice::WallLink>{{grid.index(0, 1, 0), 4, 0.3}}),
            1u);
  try {
    DistributedFluid cut(Communicator::self(), whole, 2);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("lattice.wall_rule"), std::string::npos)
        << error.what();
  }
}

// The classes are the whole lattice's, one per global node; a contrast is needed to hold them.
TEST(DistributedFluid, ViscosityClassesMustCoverTheWholeLattice) {
  lattice::FluidParameters parameters;
  parameters.inner_viscosity_ratio = 5.0;
  DistributedFluid fluid(Communicator::self(), lattice::LatticeGrid(3, 3, 4), 2, parameters);
  EXPECT_THROW(fluid.set_viscosity_classes(std::vector<lattice::ViscosityClass>(35, 0)),
               std::invalid_argument);
  DistributedFluid without(Communicator::self(), lattice::LatticeGrid(3, 3, 4), 2, {});
  EXPECT_THROW(without.set_viscosity_classes(std::vector<lattice::ViscosityClass>(36, 0)),
               std::logic_error);
}

}  // namespace
}  // namespace rbcsim::parallel
