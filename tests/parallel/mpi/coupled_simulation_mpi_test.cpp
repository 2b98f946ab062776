// The coupled loop (CoupledSimulation) on every process of an MPI run: 20 capsules in a periodic
// box sheared by a Lees-Edwards plane, pushed along z across the blocks and the periodic seam,
// touching (contact), stepped on the distributed lattice. Rank 0 compares the cells and the
// gathered fluid with the same run on one undivided solver, bit for bit: so the state is the same
// on any number of processes. A checkpoint written on all processes resumes on half of them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "contact/cell_repulsion.hpp"
#include "coupling/checkpoint.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling/snapshot.hpp"
#include "coupling_fixtures.hpp"
#include "distributed_cases.hpp"
#include "ibm/interpolation_stencil.hpp"
#include "ibm/transfer.hpp"
#include "io/atomic_file.hpp"
#include "io/sha256.hpp"
#include "io/text_file.hpp"
#include "membrane/membrane_model.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_ibm.hpp"
#include "parallel/hdf5_file.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::parallel::coupled_mpi {
namespace {

constexpr std::size_t kCells = 20;
constexpr double kPushPerVertexPN = 0.2;

// What the cells are made of: capsules in plasma, or with the physiological preset's membrane
// viscosity (an implicit friction step on the fluid nodes under each membrane, which lie on
// several processes) in a cytoplasm five times as viscous as the plasma (per-node viscosity
// classes, located every step), each cell's volume held as the preset holds it.
enum class Membrane { elastic, viscous_in_viscous_cytoplasm };

// 16 x 14 x 24 nodes (8 x 7 x 12 um), periodic, the y faces sliding at +-0.01 (lattice units).
std::unique_ptr<lattice::FluidSolver> sheared_box(Membrane membrane) {
  lattice::FluidParameters parameters;
  parameters.lees_edwards_velocity = 0.02;
  if (membrane == Membrane::viscous_in_viscous_cytoplasm) parameters.inner_viscosity_ratio = 5.0;
  return std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(16, 14, 24), parameters);
}

// 20 spheres of radius 1 um (42 vertices) on a 3 x 2 x 4 lattice of centres, away from the sliding
// plane (the IBM does not reach across it); the first rows of z straddle the periodic seam.
std::unique_ptr<coupling::CoupledSimulation> suspension(
    const Communicator& processes, contact::ContactLaw law = contact::ContactLaw::vertex,
    Membrane membrane = Membrane::elastic) {
  coupling::CouplingParameters coupling;
  coupling.processes = processes;
  coupling.block_planes = 2;
  coupling.hold_volume = membrane == Membrane::viscous_in_viscous_cytoplasm;  // as the preset
  auto simulation = std::make_unique<coupling::CoupledSimulation>(
      sheared_box(membrane), coupling::testing::plasma_units(), std::move(coupling));
  auto capsule = coupling::testing::capsule_parameters(300.0);
  if (membrane == Membrane::viscous_in_viscous_cytoplasm) {
    capsule.forces.push_back("viscosity");
    capsule.viscosity_Pa_s_um = 0.5;
  }
  std::size_t added = 0;
  for (const double z_um : {0.2, 3.2, 6.2, 9.2}) {
    for (const double y_um : {2.3, 4.7}) {
      for (const double x_um : {1.3, 3.9, 6.5}) {
        if (added == kCells) break;
        const auto sphere = coupling::testing::sphere_mesh(1, 1.0, Vec3(x_um, y_um, z_um));
        simulation->add_cell(membrane::MembraneModel(sphere, capsule), sphere.positions_um);
        ++added;
      }
    }
  }
  simulation->add_external_force([](std::size_t cell, const coupling::Cell&, std::span<Vec3> f) {
    const double direction = cell % 2 == 0 ? 1.0 : -1.0;
    for (Vec3& force : f) force.z() += direction * kPushPerVertexPN;
  });
  // The surface law's force is F(r/2) and held at its cap.
  simulation->set_cell_contact(law == contact::ContactLaw::vertex
                                   ? contact::ContactParameters{50.0, 0.5}
                                   : contact::ContactParameters{10.0, 0.5, law, 100.0},
                               "test");
  return simulation;
}

void advance(coupling::CoupledSimulation& simulation, std::size_t steps) {
  for (std::size_t step = 0; step < steps; ++step) simulation.step();
}

// Every vertex of every cell, then every stored population of the gathered fluid.
std::vector<double> state_of(coupling::CoupledSimulation& simulation) {
  simulation.gather_fluid();
  std::vector<double> state;
  for (const auto& cell : simulation.cells()) {
    for (const Vec3& p : cell.positions_lu()) state.insert(state.end(), {p.x(), p.y(), p.z()});
  }
  const auto& fluid = simulation.fluid();
  const auto populations = fluid.stored_populations(0, fluid.grid().node_count());
  state.insert(state.end(), populations.begin(), populations.end());
  return state;
}

std::size_t differing(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t count = 0;
  for (std::size_t k = 0; k < a.size(); ++k) count += a[k] != b[k] ? 1 : 0;
  return count;
}

// The run on every process against the undivided one on rank 0, after kSteps steps.
void expect_undivided_run(contact::ContactLaw law, Membrane membrane = Membrane::elastic) {
  constexpr std::size_t kSteps = 40;
  const Communicator world = Communicator::world();
  auto distributed = suspension(world, law, membrane);
  EXPECT_EQ(distributed->distributed(), world.size() > 1);
  const Vec3 start_lu = distributed->cell(0).centroid_lu();
  std::size_t steps_in_contact = 0;
  for (std::size_t step = 0; step < kSteps; ++step) {
    distributed->step();
    if (distributed->contact_statistics().pairs_in_range > 0) ++steps_in_contact;
  }
  const auto state = state_of(*distributed);
  if (!world.is_root()) return;
  auto undivided = suspension(Communicator::self(), law, membrane);
  advance(*undivided, kSteps);
  const auto expected = state_of(*undivided);
  if (membrane == Membrane::viscous_in_viscous_cytoplasm) {
    // The friction steps ran (every second step, the AA kernel's natural layout) and iterated.
    EXPECT_GT(undivided->cell(0).friction_iterations(), 0u);
    EXPECT_GT(distributed->cell(kCells - 1).friction_iterations(), 0u);
    EXPECT_EQ(distributed->cell(kCells - 1).friction_iterations(),
              undivided->cell(kCells - 1).friction_iterations());
  }
  // The cells moved (pushed along z, carried along x by the shear), not a still state, and
  // touched.
  EXPECT_GT((undivided->cell(0).centroid_lu() - start_lu).norm(), 0.01);
  EXPECT_GT(steps_in_contact, 0u);
  EXPECT_EQ(differing(state, expected), 0u)
      << "of " << expected.size() << " values on " << world.size() << " processes";
}

TEST(ProcessesCoupledSimulation, TwentyCellsMoveAsOnTheUndividedLatticeBitForBit) {
  expect_undivided_run(contact::ContactLaw::vertex);
}

// The surface law, whose nearest-point search each process does for the cells it computes
// (CoupledSimulation::computes_cell).
TEST(ProcessesCoupledSimulation, TwentyCellsInSurfaceContactMoveAsOnTheUndividedLatticeBitForBit) {
  expect_undivided_run(contact::ContactLaw::surface);
}

// The physiological preset's membrane and cytoplasm: each cell's friction solved by the process
// that computes it, from the moments of nodes on several processes; the classes located on every
// process.
TEST(ProcessesCoupledSimulation, TwentyViscousCellsInAViscousCytoplasmMoveAsOnTheUndividedLattice) {
  expect_undivided_run(contact::ContactLaw::vertex, Membrane::viscous_in_viscous_cytoplasm);
}

// Written on every process of the run, resumed on the first half of them (4 -> 2, 3 -> 2, 2 -> 1):
// the uninterrupted undivided run's state, bit for bit. Only rank 0 writes files (cli/main.cpp).
// With membrane viscosity the friction's warm start rides in the checkpoint too.
void expect_resumed_on_half(Membrane membrane) {
  constexpr std::size_t kBefore = 17;
  constexpr std::size_t kAfter = 13;
  const Communicator world = Communicator::world();
  io::set_process_writes_files(world.is_root());
  const auto file = testing::checkpoint_file(world, "rbcsim_mpi_coupled_");
  const auto law = contact::ContactLaw::vertex;
  {
    auto simulation = suspension(world, law, membrane);
    advance(*simulation, kBefore);
    coupling::write_checkpoint(file, *simulation, "mpi test");
  }
  world.barrier();
  const int half = (world.size() + 1) / 2;
  const Communicator part = world.split(world.rank() < half ? 0 : 1);
  if (world.rank() < half) {
    auto resumed = suspension(part, law, membrane);
    coupling::read_checkpoint(file, *resumed, "mpi test");
    advance(*resumed, kAfter);
    const auto state = state_of(*resumed);
    if (world.is_root()) {
      auto uninterrupted = suspension(Communicator::self(), law, membrane);
      advance(*uninterrupted, kBefore + kAfter);
      EXPECT_EQ(differing(state, state_of(*uninterrupted)), 0u)
          << "written on " << world.size() << ", resumed on " << half;
    }
  }
  world.barrier();
  io::set_process_writes_files(true);
  if (world.is_root()) std::filesystem::remove(file);
}

TEST(ProcessesCoupledSimulation, CheckpointWrittenOnAllResumesOnHalfBitForBit) {
  expect_resumed_on_half(Membrane::elastic);
}

TEST(ProcessesCoupledSimulation, ViscousCellsCheckpointedOnAllResumeOnHalfBitForBit) {
  expect_resumed_on_half(Membrane::viscous_in_viscous_cytoplasm);
}

// The SHA-256 of a file's bytes (a differing snapshot prints two digests, not megabytes).
std::string file_digest(const std::filesystem::path& path) {
  const std::string bytes = io::read_text_file(path);
  return io::sha256_hex(std::as_bytes(std::span<const char>(bytes)));
}

// The 20 capsules' HDF5 snapshots (cells and fluid, every 10 steps), each process writing its
// slab's planes and the cells it owns: the same files, byte for byte, as the undivided run writes
// on one process, so on any process count.
TEST(ProcessesCoupledSimulation, TwentyCellsHdf5SnapshotsAreTheUndividedRunsBytes) {
  if (!built_with_hdf5()) GTEST_SKIP() << "built without HDF5 (RBCSIM_HDF5)";
  constexpr std::size_t kSteps = 20;
  const Communicator world = Communicator::world();
  io::set_process_writes_files(world.is_root());
  const auto base = testing::checkpoint_file(world, "rbcsim_mpi_hdf5_");
  const auto written = std::filesystem::path(base).replace_extension(".distributed");
  const auto expected = std::filesystem::path(base).replace_extension(".undivided");
  const coupling::SnapshotIntervals every_ten{10, 10, coupling::SnapshotFormat::hdf5};
  {
    auto distributed = suspension(world);
    coupling::add_hdf5_output(*distributed, written, every_ten,
                              std::vector<std::int32_t>(kCells, 1));
    distributed->observe_all();
    advance(*distributed, kSteps);
  }
  world.barrier();
  io::set_process_writes_files(true);
  if (!world.is_root()) return;
  {
    auto undivided = suspension(Communicator::self());
    coupling::add_hdf5_output(*undivided, expected, every_ten,
                              std::vector<std::int32_t>(kCells, 1));
    undivided->observe_all();
    advance(*undivided, kSteps);
  }
  std::size_t compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(expected)) {
    if (!entry.is_regular_file()) continue;
    const auto relative = std::filesystem::relative(entry.path(), expected);
    EXPECT_EQ(file_digest(written / relative), file_digest(entry.path()))
        << relative << " on " << world.size() << " processes";
    ++compared;
  }
  // Three snapshots (steps 0, 10, 20) of cells and fluid, and the two .xdmf.
  EXPECT_EQ(compared, 8u);
  std::filesystem::remove_all(written);
  std::filesystem::remove_all(expected);
}

// Slabs as thin as they come (2 planes, and 3 at the top; 2 x processes + 1 planes in all) and
// points whose stencils reach across the periodic seam from the top slab into the bottom one and
// back, with each kernel: the velocities are those interpolated on one undivided solver, bit for
// bit. (A ghost plane taken from the wrong side of the seam stops the run.)
TEST(ProcessesThinSlabs, VerticesAcrossTheSeamInterpolateAsOnTheUndividedLattice) {
  const Communicator world = Communicator::world();
  const lattice::LatticeGrid grid(6, 5, 2 * world.size() + 1);
  const auto velocity_at = [](int x, int y, int z) {
    return std::array<double, 3>{0.01 * std::sin(0.7 * z + 0.3 * x), 0.004 * y,
                                 0.002 * std::cos(1.1 * z)};
  };
  DistributedFluid distributed(world, grid, 2, {});
  distributed.initialise_equilibrium([&](int x, int y, int z) {
    return DistributedFluid::NodeState{1.0, velocity_at(x, y, z)};
  });
  distributed.step();
  lattice::FluidSolver undivided(grid, {});
  std::vector<double> density(grid.node_count(), 1.0);
  lattice::VectorField velocity{std::vector<double>(grid.node_count()),
                                std::vector<double>(grid.node_count()),
                                std::vector<double>(grid.node_count())};
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    const auto c = grid.coordinates(node);
    const auto u = velocity_at(c[0], c[1], c[2]);
    for (int axis = 0; axis < 3; ++axis) velocity[axis][node] = u[axis];
  }
  undivided.initialise_equilibrium(density, velocity);
  undivided.step();
  const double top = grid.nz() - 0.5;
  const std::vector<Vec3> positions = {{2.3, 2.1, top},        {3.1, 1.7, top + 0.3},
                                       {1.2, 3.3, 0.2},        {4.4, 2.2, -0.4},
                                       {2.5, 2.5, 2.0 + 0.61}, {0.7, 1.1, grid.nz() - 2.2}};
  const ibm::GridView view{grid.nx(), grid.ny(), grid.nz(), true, true, true};
  for (const char* kernel : {"phi2", "phi3", "phi4"}) {
    DistributedImmersedBoundary points(distributed, kernel);
    points.build(positions);
    const auto interpolated = points.interpolate(distributed);
    ibm::InterpolationStencil stencil;
    stencil.build(ibm::find_delta_kernel(kernel), view, positions);
    std::vector<Vec3> expected(positions.size());
    const auto& u = undivided.velocity();
    ibm::interpolate_velocity(stencil, view, u[0].data(), u[1].data(), u[2].data(), expected);
    for (std::size_t p = 0; p < positions.size(); ++p) {
      EXPECT_EQ(interpolated[p], expected[p])
          << kernel << ", point " << p << " on " << world.size() << " processes";
    }
  }
}

}  // namespace
}  // namespace rbcsim::parallel::coupled_mpi
