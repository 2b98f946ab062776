// Flows run on the distributed lattice and on one undivided FluidSolver, for the equality tests of
// tests/parallel (one process) and tests/parallel/mpi (1-4 processes under mpirun).
#pragma once

#include "lattice/fluid_solver.hpp"
#include "parallel/communicator.hpp"
#include "parallel/distributed_fluid.hpp"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::parallel::testing {

struct DistributedCase {
  std::string name;
  lattice::FluidParameters parameters;
  bool walls = true;         // walls at y = 0 and y = ny - 1 (a channel)
  bool force_field = false;  // a force density that varies in space and time, added every step
  HaloScheme scheme = HaloScheme::automatic;
  bool obstacle = false;  // with walls: also a block across the channel, straddling slab faces
  // A viscosity contrast (parameters.inner_viscosity_ratio) with classes that vary from node to
  // node in a blob straddling slab faces (DistributedFluid::set_viscosity_classes).
  bool viscosity_classes = false;
};

// GoogleTest prints a case by its name.
inline void PrintTo(const DistributedCase& flow, std::ostream* out) { *out << flow.name; }

// Every case of the equality tests: the AA kernel in double and single precision, the reference
// kernel, a force field, Lees-Edwards, a viscosity contrast; the AA kernel's cases with both halo
// schemes.
std::vector<DistributedCase> distributed_cases();

inline constexpr int kCaseNx = 6;
inline constexpr int kCaseNy = 7;
inline constexpr int kCaseNz = 12;
// An odd count: the AA kernel ends in its swapped layout.
inline constexpr std::size_t kCaseSteps = 25;

// The case of that name; throws std::logic_error if there is none.
DistributedCase case_named(std::string_view name);

// The case's lattice, walls and start, undivided or on the distributed lattice (blocks of 2
// planes), and steps of it (the force field, if any, added before each).
std::unique_ptr<lattice::FluidSolver> make_undivided(const DistributedCase& flow);
void advance_undivided(const DistributedCase& flow, lattice::FluidSolver& solver,
                       std::size_t steps);
std::unique_ptr<DistributedFluid> make_distributed(const DistributedCase& flow,
                                                   const Communicator& communicator);
void advance_distributed(const DistributedCase& flow, DistributedFluid& fluid, std::size_t steps);

// The populations as stored after kCaseSteps steps on the undivided solver (FluidSolver's
// stored_populations(0, node_count) order).
std::vector<double> run_undivided(const DistributedCase& flow);
// The same on the distributed lattice (blocks of 2 planes); rank 0 gets the gathered state, the
// other ranks an empty vector.
std::vector<double> run_distributed(const DistributedCase& flow, const Communicator& communicator);

// A mini coupled loop: points anchored by springs and pushed along z, so that they cross block
// boundaries and the periodic seam; their forces spread, the fluid stepped, their velocities
// interpolated with the same stencil, the points moved (forward Euler); `steps` steps in the
// channel of the first case, with the IBM kernel `kernel`.
struct CoupledState {
  std::vector<double> populations;  // as stored, global order
  std::vector<double> positions;    // x, y, z of every point
};
CoupledState run_coupled_undivided(std::string_view kernel, std::size_t steps);
// Rank 0 gets the state; the other ranks empty vectors.
CoupledState run_coupled_distributed(std::string_view kernel, std::size_t steps,
                                     const Communicator& communicator);

// A tube flow as the capillary sets it up, on 8 x 6 x 12 nodes: a velocity inlet (a moving wall)
// at x = 0 with a profile, a pressure outlet at x = nx - 1, resting walls at y = 0 and moving ones
// at y = ny - 1, every link into them cut at 0.3 (y = 0) or 0.7 (y = ny - 1), straight and
// diagonal, some of them across z (so that the node behind a link lies on the next plane); the
// kernel and wall rule given (half-way: the links are closed half-way anyway). Then `steps`
// steps from a uniform flow.
std::unique_ptr<lattice::FluidSolver> make_tube_channel(const std::string& kernel,
                                                        const std::string& wall_rule,
                                                        std::size_t steps);
// The stored populations at the fluid nodes only (a solid node's are never read; the reference
// kernel's second buffer keeps there what its solver was built with, which a restored state does
// not carry), from FluidSolver::stored_populations(0, node_count)'s order.
std::vector<double> at_fluid_nodes(const lattice::FluidSolver& solver,
                                   std::span<const double> stored_populations);

// A checkpoint file every process names alike (collective): rank 0's process id, after `prefix`,
// in the temporary directory.
std::filesystem::path checkpoint_file(const Communicator& world, const std::string& prefix);

}  // namespace rbcsim::parallel::testing
