// The lattice Boltzmann fluid across processes: each process runs the ordinary FluidSolver (any
// kernel, either precision, Lees-Edwards in y) on its slab of z-planes (block_decomposition.hpp)
// plus kHaloPlanes ghost planes on each side, which the halo exchange fills from the neighbours.
// Two exchanges, a reference and an optimised twin (HaloScheme), both exact:
//
// - full state, before every step: the neighbours' two boundary planes, every population as
//   stored and the force density, into the two ghost planes. A ghost node then collides exactly as
//   its owner does, and the inner ghost plane gathers only exact values, so what it streams into
//   the slab is what the owner's node streams there; the outer plane's garbage (it gathers across
//   the local wrap) only lands in ghost planes. Any kernel.
// - crossing populations, for the AA kernel (optimised_kernel.hpp) without a Lees-Edwards plane
//   (whose crossing populations take their source's density and velocity, which a ghost plane
//   only has exactly with the full state): nothing at its local step
//   (node by node), and at its streaming step only the five populations that cross each face, one
//   plane: before it, the post-collision populations leaving the boundary plane into the
//   neighbour's ghost plane (which its boundary nodes gather from); after it, what the boundary
//   nodes scattered into their ghost plane back into the neighbour's boundary plane, over the
//   ghost's own (meaningless) scatter, except where the ghost node is a wall (the boundary node
//   bounced that population back itself). 10 of the 76 plane-populations per face and two steps the
//   full state moves, and no force density: the ghosts' collisions never reach the slab.
//
// Either way every node of a slab computes what the same node of one undivided solver computes,
// from the same values in the same order: the state is bit-identical on any number of processes,
// and to FluidSolver on the whole lattice (tests/parallel).
//
// The lattice is periodic in z, as FluidSolver's is: the lowest slab's lower neighbour is the
// highest slab. Checkpoints take the undivided solver's form (save_state), so they do not depend on
// the process count; they pass through rank 0 whole (MPI counts are ints: at most 2^31 - 1
// values, some 113 million nodes, refused beyond). Moving walls, velocity inlets and pressure
// outlets come with an undivided solver cut into slabs (its constructor), and so do curved walls
// (interpolated wall links, which read the node behind and therefore take the full-state halo),
// and a viscosity contrast with its classes (set_viscosity_classes). Densities
// and velocities are the slab's own; the ghost planes' are not kept (distributed_ibm.hpp exchanges
// the velocities it needs).
#pragma once

#include "common/state_archive.hpp"
#include "common/vec3.hpp"
#include "lattice/fluid_solver.hpp"
#include "lattice/lattice_grid.hpp"
#include "parallel/block_decomposition.hpp"
#include "parallel/communicator.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::parallel {

inline constexpr int kHaloPlanes = 2;
inline constexpr std::uint32_t kFluidCheckpointVersion = 1;

enum class HaloScheme {
  automatic,  // crossing populations where they fit, else the full state
  full_state,
  crossing_populations,  // the optimised kernel without a Lees-Edwards plane
};

// Whether the node at global (x, y, z) is a resting wall (half-way bounce-back).
using WallPredicate = std::function<bool(int x, int y, int z)>;

// What the halo exchanges of this process cost so far.
struct HaloCounters {
  std::size_t exchanges = 0;  // full state: one per step; crossing: two per streaming step
  std::size_t messages = 0;   // sent by this process
  std::size_t bytes = 0;      // sent by this process
  double seconds = 0.0;       // packing, sending, receiving and unpacking
};

class DistributedFluid {
 public:
  // Every process of `communicator` constructs it with the same arguments (collective). Blocks of
  // `block_planes` planes, weighted by their fluid nodes. Throws rbcsim::InputError for a
  // decomposition that does not fit (block_decomposition.hpp), std::logic_error for crossing
  // populations where they do not fit.
  DistributedFluid(Communicator communicator, lattice::LatticeGrid global, int block_planes,
                   lattice::FluidParameters parameters, const WallPredicate& is_wall = {},
                   HaloScheme scheme = HaloScheme::automatic);
  // The undivided solver `whole` (the same on every process, collective) cut into slabs: its
  // lattice, parameters, boundaries (walls resting or moving, velocity inlets, pressure outlets)
  // and state (populations, moments, step count), so that a case set up for one process runs on
  // many; curved wall links under an interpolated rule take the full-state halo. Throws as the
  // constructor above.
  DistributedFluid(Communicator communicator, const lattice::FluidSolver& whole, int block_planes);
  HaloScheme halo_scheme() const { return scheme_; }

  const Communicator& communicator() const { return communicator_; }
  const lattice::LatticeGrid& global_grid() const { return global_; }
  const BlockDecomposition& decomposition() const { return decomposition_; }
  // This process's planes [z_begin(), z_end()) of the global lattice.
  int z_begin() const { return decomposition_.z_begin(communicator_.rank()); }
  int z_end() const { return decomposition_.z_end(communicator_.rank()); }
  // The local solver: the slab with its ghost planes (global plane z at local z - z_begin() +
  // kHaloPlanes). Read densities and velocities of the slab's own planes; the ghost planes'
  // values are the neighbours' business.
  // Read-only: geometry, forces and state go through this class, so that ghost planes and halo
  // masks stay consistent with the slab (walls only through the constructor's predicate).
  const lattice::FluidSolver& local() const { return local_; }
  // The walls the fluid was built with (empty: none), for the stencils of its immersed boundary.
  const WallPredicate& walls() const { return walls_; }
  // The local index of global node (x, y, z), for z in [z_begin() - kHaloPlanes, z_end() +
  // kHaloPlanes) (not wrapped).
  std::size_t local_node(int x, int y, int z) const;
  // The local index of global node `global_node` (grid order of the whole lattice) if it lies in
  // this slab's own planes, else -1.
  std::int64_t own_local_index(std::size_t global_node) const;

  // Equilibrium at rest or moving, every node of the slab and its ghosts.
  void initialise_equilibrium(double density, const std::array<double, 3>& velocity);
  // Equilibrium at the density and velocity `state` gives for each global node (x, y, z).
  struct NodeState {
    double density = 1.0;
    std::array<double, 3> velocity = {0.0, 0.0, 0.0};
  };
  void initialise_equilibrium(const std::function<NodeState(int x, int y, int z)>& state);
  // The local force density (grid order of the local solver): add forces at the slab's own nodes;
  // the next step copies the ghost planes' from the neighbours.
  lattice::VectorField& force_density();

  // The membrane viscosity's implicit step (coupling/membrane_friction.hpp) across the slabs.
  // Whether the populations are in natural layout now (the same on every process).
  bool populations_natural() const { return local_.populations_natural(); }
  // For each node of `global_nodes` (global indices) in this slab's own planes, its pre-collision
  // density and momentum (FluidSolver::pre_collision_moments) appended to `values` as six numbers:
  // `label`, the node's position in `global_nodes`, the density, the momentum's x, y, z.
  void append_own_pre_collision_moments(std::span<const std::size_t> global_nodes, double label,
                                        std::vector<double>& values) const;
  // FluidSolver::add_momentum of momentum[k] at global node global_nodes[k], for the nodes in
  // this slab's own planes (the other nodes are their owners' to add; the next step's halo
  // exchange carries the change to the ghost planes).
  void add_momentum_on_own_nodes(std::span<const std::size_t> global_nodes,
                                 std::span<const Vec3> momentum);
  // With a viscosity contrast (lattice::FluidParameters::inner_viscosity_ratio): the classes of
  // the whole lattice, one per global node in grid order (what coupling/cytoplasm_indicator.hpp
  // writes on the undivided solver), copied into the slab and its ghost planes, so that every
  // node collides with the rates of its class as on the undivided solver. Throws
  // std::logic_error without a contrast, std::invalid_argument for a wrong count.
  void set_viscosity_classes(std::span<const lattice::ViscosityClass> global_classes);

  // Collective: the halo exchange, then one step of the local solver.
  void step();
  void advance(std::size_t steps);

  // Collective: lattice::FluidSolver::run_to_steady_state across the slabs, each measuring its own
  // planes and the maxima combined exactly: the same steps, the same state and the same result as
  // the undivided solver's, on every process. Throws rbcsim::RuntimeFailure on every process for a
  // non-finite velocity anywhere.
  lattice::SteadyStateResult run_to_steady_state(const lattice::SteadyStateCriterion& criterion);

  // Collective. The sum of the populations of every fluid node: per plane in grid order, the
  // planes in global order on rank 0, the same value returned on every process.
  double total_mass() const;
  // Collective. Rank 0: the populations of the whole lattice as stored, population i of global
  // node n at [i * node_count + n] (FluidSolver::stored_populations(0, node_count)'s order);
  // other ranks: empty.
  std::vector<double> gather_stored_populations() const;
  // Collective. Rank 0: the SHA-256 of gather_stored_populations()'s bytes; other ranks: empty.
  std::string state_sha256() const;
  // Collective. Throws rbcsim::RuntimeFailure on every process if a fluid node of any slab has a
  // non-finite velocity, naming the global node on the process that found it.
  void require_finite_velocity() const;

  // Collective checkpoints in the undivided solver's form (FluidSolver::save_state's arrays over
  // the whole lattice, global order): written on N processes, restored on M, or into one
  // FluidSolver, and back. save_state fills `archive` on rank 0 (nothing elsewhere);
  // restore_state takes rank 0's archive (the others' is not read) and throws
  // rbcsim::InputError on every process, naming the archive on rank 0, if an array is missing or
  // does not fit this lattice. The geometry is not saved: restore into a fluid set up the same way.
  void save_state(StateArchive& archive) const;
  void restore_state(StateArchive& archive);
  // The same through a checkpoint file (io/state_archive_file.hpp, version
  // kFluidCheckpointVersion), written and read by rank 0. Reading throws rbcsim::InputError on
  // every process for a file that is missing, corrupt, of another version or fingerprint, or
  // that does not fit.
  void write_checkpoint(const std::filesystem::path& file,
                        std::string_view config_fingerprint) const;
  void read_checkpoint(const std::filesystem::path& file, std::string_view config_fingerprint);

  const HaloCounters& halo_counters() const { return counters_; }
  // Collective: the state (save_state's arrays) copied into `whole`, an undivided solver of the
  // same lattice set up the same way, on every process.
  void copy_state_into(lattice::FluidSolver& whole) const;

 private:
  // A per-node field of the local solver with `components` arrays of the local node count, back
  // to back: rank 0 gets the slabs' own planes in global order (components arrays of the global
  // node count), the others nothing.
  std::vector<double> gather_field(std::span<const double> local, int components) const;
  // The reverse, ghost planes included (wrapped around the lattice): rank 0's global field cut
  // into every process's local field.
  std::vector<double> scatter_field(std::span<const double> global, int components) const;
  // The nodes of `global_nodes` in this slab's own planes: their positions in `global_nodes`
  // (ascending) and their local indices.
  struct OwnNodes {
    std::vector<std::size_t> positions;
    std::vector<std::size_t> local_nodes;
  };
  OwnNodes own_nodes(std::span<const std::size_t> global_nodes) const;
  // The populations of `planes` planes from local_z, and their force density when `force`.
  std::vector<double> pack_planes(int local_z, int planes, bool force) const;
  void unpack_planes(int local_z, int planes, const std::vector<double>& values, bool force);
  void exchange_full_state();
  // Sends slots `up_slots` of local plane `up_from` to the upper neighbour's plane `up_to` and
  // slots `down_slots` of `down_from` to the lower neighbour's `down_to`. With masks (one entry
  // per received value), only the values whose entry is set replace the plane's own.
  void exchange_slots(int up_from, int up_to, std::span<const int> up_slots, int down_from,
                      int down_to, std::span<const int> down_slots,
                      const std::vector<char>* up_mask = nullptr,
                      const std::vector<char>* down_mask = nullptr);
  // For the boundary plane next to the ghost plane `ghost` and the slots `slots` (pointing from
  // the ghost into the slab): whether each value arrives over a plain fluid link from the ghost
  // plane, so that after the streaming step it is the ghost's scatter, to be replaced by the
  // neighbour's. Not so where the ghost node is a wall: the boundary node bounced the population
  // back itself.
  std::vector<char> streamed_from_ghost(int ghost, std::span<const int> slots) const;

  Communicator communicator_;
  lattice::LatticeGrid global_;
  BlockDecomposition decomposition_;
  lattice::FluidSolver local_;
  HaloScheme scheme_;
  std::vector<char> bottom_from_ghost_;  // streamed_from_ghost of the lowest plane, up slots
  std::vector<char> top_from_ghost_;     // of the highest plane, down slots
  WallPredicate walls_;
  // Whether force_density() was handed out here. The full-state halo sends the force density once
  // any process has (the undivided solver's one force field is on once anyone adds to it).
  bool force_field_ = false;
  bool force_in_halo_ = false;  // some process has applied a force: the halo carries it from now
  HaloCounters counters_;
};

// Collective: `whole` (the same on every process) run to its steady state across the processes
// of `communicator` in blocks of `block_planes` planes, and the state copied back into `whole` on
// every process: what whole.run_to_steady_state(criterion) gives on one process, bit for bit, in
// a fraction of its time. On one process it is that call.
lattice::SteadyStateResult run_to_steady_state(const Communicator& communicator,
                                               lattice::FluidSolver& whole, int block_planes,
                                               const lattice::SteadyStateCriterion& criterion);

}  // namespace rbcsim::parallel
