#include "parallel/distributed_fluid.hpp"

#include "common/errors.hpp"
#include "io/sha256.hpp"
#include "io/state_archive_file.hpp"
#include "lattice/d3q19.hpp"
#include "lattice/wall_link.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rbcsim::parallel {

namespace {

constexpr int kUpwardTag = 1;
constexpr int kDownwardTag = 2;

// The blocks of `block_planes` planes weighted by their fluid nodes.
BlockDecomposition weighted_blocks(const lattice::LatticeGrid& global, int block_planes, int ranks,
                                   const WallPredicate& is_wall) {
  const BlockDecomposition layout(global.nz(), block_planes, 1);
  std::vector<std::int64_t> weights(layout.block_count(), 0);
  for (int block = 0; block < layout.block_count(); ++block) {
    for (int z = layout.block_z_begin(block); z < layout.block_z_begin(block + 1); ++z) {
      for (int y = 0; y < global.ny(); ++y) {
        for (int x = 0; x < global.nx(); ++x) {
          if (!is_wall || !is_wall(x, y, z)) ++weights[block];
        }
      }
    }
  }
  return BlockDecomposition(global.nz(), block_planes, ranks, weights);
}

// Slots by the z component of their direction: +1 (up) and -1 (down), five each in D3Q19.
std::vector<int> slots_moving(int z_direction) {
  std::vector<int> slots;
  for (int i = 0; i < lattice::kDirections; ++i) {
    if (lattice::kVelocities[i][2] == z_direction) slots.push_back(i);
  }
  return slots;
}

// The crossing populations need the AA kernel, and no sliding plane: a population crossing the
// Lees-Edwards plane takes the density and velocity of its source node (its Galilean shift),
// which in a ghost plane only the full state keeps exact.
HaloScheme chosen_scheme(HaloScheme scheme, const lattice::FluidParameters& parameters) {
  const bool crossing_fits =
      parameters.kernel == "optimised" && !parameters.lees_edwards_velocity.has_value();
  if (scheme == HaloScheme::automatic) {
    return crossing_fits ? HaloScheme::crossing_populations : HaloScheme::full_state;
  }
  if (scheme == HaloScheme::crossing_populations && !crossing_fits) {
    throw std::logic_error(
        "parallel: the crossing-populations halo needs the optimised kernel and no Lees-Edwards "
        "plane");
  }
  return scheme;
}

// The nodes of an undivided solver that are not fluid (walls, velocity inlets, pressure outlets),
// none without any. Every rule is the boundary node's own business, but the interpolated walls'
// also read the node behind (x + c), which may sit in a ghost plane: they take the full-state
// halo (curved_walls_of), whose inner ghost plane collides exactly as its owner does. (The
// crossing populations include the one read there and gave the same bits in the tests, but
// their exactness for it is not argued; the full state's is.)
WallPredicate solid_nodes_of(const lattice::FluidSolver& whole) {
  const auto& kinds = whole.solid_mask();
  if (std::ranges::none_of(kinds, [](std::uint8_t kind) { return kind != 0; })) return {};
  auto mask = std::make_shared<const std::vector<std::uint8_t>>(kinds);
  const lattice::LatticeGrid grid = whole.grid();
  return [mask, grid](int x, int y, int z) { return (*mask)[grid.index(x, y, z)] != 0; };
}

// Whether `whole` has wall links that its wall rule does not close half-way (curved walls).
bool curved_walls_of(const lattice::FluidSolver& whole) {
  return whole.boundaries().has_wall_fractions() && whole.parameters().wall_rule != "halfway";
}

}  // namespace

DistributedFluid::DistributedFluid(Communicator communicator, const lattice::FluidSolver& whole,
                                   int block_planes)
    : DistributedFluid(std::move(communicator), whole.grid(), block_planes, whole.parameters(),
                       solid_nodes_of(whole),
                       curved_walls_of(whole) ? HaloScheme::full_state : HaloScheme::automatic) {
  // The constructor made every solid node a resting wall; the moving ones and the outlets, with
  // their velocities and densities, as the undivided solver has them, and the wall links the
  // undivided solver cuts other than half-way (links never set are half-way there and here).
  const lattice::BoundaryMap& boundaries = whole.boundaries();
  const lattice::LatticeGrid& grid = local_.grid();
  std::vector<lattice::WallLink> links;
  for (int z = 0; z < grid.nz(); ++z) {
    const int global_z = lattice::LatticeGrid::wrap(z_begin() - kHaloPlanes + z, global_.nz());
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        const std::size_t node = global_.index(x, y, global_z);
        const std::size_t here = grid.index(x, y, z);
        if (boundaries.kind(node) == lattice::NodeKind::pressure_outlet) {
          local_.set_pressure_outlet(here, boundaries.outlet_density(node));
        } else if (boundaries.kind(node) == lattice::NodeKind::wall) {
          const auto velocity = boundaries.wall_velocity(node);
          if (velocity != std::array<double, 3>{0.0, 0.0, 0.0}) local_.set_wall(here, velocity);
        } else if (boundaries.has_wall_fractions()) {
          for (int i = 1; i < lattice::kDirections; ++i) {
            const double fraction = boundaries.wall_fraction(node, i);
            if (fraction != lattice::kHalfwayFraction) links.push_back({here, i, fraction});
          }
        }
      }
    }
  }
  if (!links.empty()) local_.set_wall_links(links);
  StateArchive state("the undivided fluid");
  whole.save_state(state);
  restore_state(state);
  if (whole.has_viscosity_contrast()) set_viscosity_classes(whole.viscosity_classes());
}

DistributedFluid::DistributedFluid(Communicator communicator, lattice::LatticeGrid global,
                                   int block_planes, lattice::FluidParameters parameters,
                                   const WallPredicate& is_wall, HaloScheme scheme)
    : communicator_(std::move(communicator)),
      global_(global),
      decomposition_(weighted_blocks(global, block_planes, communicator_.size(), is_wall)),
      local_(
          lattice::LatticeGrid(global.nx(), global.ny(),
                               decomposition_.z_end(communicator_.rank()) -
                                   decomposition_.z_begin(communicator_.rank()) + 2 * kHaloPlanes),
          parameters),
      scheme_(chosen_scheme(scheme, parameters)),
      walls_(is_wall) {
  const lattice::LatticeGrid& grid = local_.grid();
  for (int z = 0; z < grid.nz() && is_wall; ++z) {
    const int global_z = lattice::LatticeGrid::wrap(z_begin() - kHaloPlanes + z, global_.nz());
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        if (is_wall(x, y, global_z)) local_.set_wall(grid.index(x, y, z));
      }
    }
  }
  const int bottom = kHaloPlanes;
  const int top = z_end() - z_begin() + kHaloPlanes - 1;
  bottom_from_ghost_ = streamed_from_ghost(bottom - 1, slots_moving(+1));
  top_from_ghost_ = streamed_from_ghost(top + 1, slots_moving(-1));
}

std::vector<char> DistributedFluid::streamed_from_ghost(int ghost,
                                                        std::span<const int> slots) const {
  const lattice::LatticeGrid& grid = local_.grid();
  std::vector<char> mask;
  mask.reserve(slots.size() * grid.nx() * grid.ny());
  for (const int i : slots) {
    const auto& c = lattice::kVelocities[i];
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        const std::size_t source =
            grid.index(lattice::LatticeGrid::wrap(x - c[0], grid.nx()),
                       lattice::LatticeGrid::wrap(y - c[1], grid.ny()), ghost);
        mask.push_back(local_.boundaries().is_fluid(source) ? 1 : 0);
      }
    }
  }
  return mask;
}

std::size_t DistributedFluid::local_node(int x, int y, int z) const {
  return local_.grid().index(x, y, z - z_begin() + kHaloPlanes);
}

void DistributedFluid::initialise_equilibrium(double density,
                                              const std::array<double, 3>& velocity) {
  local_.initialise_equilibrium(density, velocity);
}

void DistributedFluid::initialise_equilibrium(
    const std::function<NodeState(int x, int y, int z)>& state) {
  const lattice::LatticeGrid& grid = local_.grid();
  std::vector<double> density(grid.node_count());
  lattice::VectorField velocity;
  for (auto& component : velocity) component.resize(grid.node_count());
  for (int z = 0; z < grid.nz(); ++z) {
    const int global_z = lattice::LatticeGrid::wrap(z_begin() - kHaloPlanes + z, global_.nz());
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        const NodeState node_state = state(x, y, global_z);
        const std::size_t node = grid.index(x, y, z);
        density[node] = node_state.density;
        for (int axis = 0; axis < 3; ++axis) velocity[axis][node] = node_state.velocity[axis];
      }
    }
  }
  local_.initialise_equilibrium(density, velocity);
}

std::int64_t DistributedFluid::own_local_index(std::size_t global_node) const {
  const std::size_t plane_size = static_cast<std::size_t>(global_.nx()) * global_.ny();
  const auto z = static_cast<int>(global_node / plane_size);
  if (z < z_begin() || z >= z_end()) return -1;
  return static_cast<std::int64_t>(global_node % plane_size +
                                   static_cast<std::size_t>(z - z_begin() + kHaloPlanes) *
                                       plane_size);
}

DistributedFluid::OwnNodes DistributedFluid::own_nodes(
    std::span<const std::size_t> global_nodes) const {
  OwnNodes own;
  for (std::size_t k = 0; k < global_nodes.size(); ++k) {
    const std::int64_t local = own_local_index(global_nodes[k]);
    if (local < 0) continue;
    own.positions.push_back(k);
    own.local_nodes.push_back(static_cast<std::size_t>(local));
  }
  return own;
}

void DistributedFluid::append_own_pre_collision_moments(std::span<const std::size_t> global_nodes,
                                                        double label,
                                                        std::vector<double>& values) const {
  const OwnNodes own = own_nodes(global_nodes);
  std::vector<double> density(own.local_nodes.size());
  std::vector<Vec3> momentum(own.local_nodes.size());
  local_.pre_collision_moments(own.local_nodes, density, momentum);
  for (std::size_t k = 0; k < own.local_nodes.size(); ++k) {
    values.insert(values.end(), {label, static_cast<double>(own.positions[k]), density[k],
                                 momentum[k].x(), momentum[k].y(), momentum[k].z()});
  }
}

void DistributedFluid::add_momentum_on_own_nodes(std::span<const std::size_t> global_nodes,
                                                 std::span<const Vec3> momentum) {
  if (momentum.size() != global_nodes.size()) {
    throw std::invalid_argument("parallel: momentum for " + std::to_string(momentum.size()) +
                                " of " + std::to_string(global_nodes.size()) + " nodes");
  }
  const OwnNodes own = own_nodes(global_nodes);
  std::vector<Vec3> own_momentum;
  own_momentum.reserve(own.positions.size());
  for (const std::size_t k : own.positions) own_momentum.push_back(momentum[k]);
  local_.add_momentum(own.local_nodes, own_momentum);
}

void DistributedFluid::set_viscosity_classes(
    std::span<const lattice::ViscosityClass> global_classes) {
  if (global_classes.size() != global_.node_count()) {
    throw std::invalid_argument("parallel: " + std::to_string(global_classes.size()) +
                                " viscosity classes for " + std::to_string(global_.node_count()) +
                                " nodes");
  }
  const std::span<lattice::ViscosityClass> classes = local_.viscosity_classes();
  const std::size_t plane_size = static_cast<std::size_t>(global_.nx()) * global_.ny();
  const int planes = local_.grid().nz();
  for (int z = 0; z < planes; ++z) {
    const int global_z = lattice::LatticeGrid::wrap(z_begin() - kHaloPlanes + z, global_.nz());
    const auto from = global_classes.begin() +
                      static_cast<std::ptrdiff_t>(static_cast<std::size_t>(global_z) * plane_size);
    std::copy(
        from, from + static_cast<std::ptrdiff_t>(plane_size),
        classes.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(z) * plane_size));
  }
}

lattice::VectorField& DistributedFluid::force_density() {
  force_field_ = true;
  return local_.force_density();
}

std::vector<double> DistributedFluid::pack_planes(int local_z, int planes, bool force) const {
  const lattice::LatticeGrid& grid = local_.grid();
  const std::size_t first = grid.index(0, 0, local_z);
  const std::size_t count = static_cast<std::size_t>(planes) * grid.nx() * grid.ny();
  std::vector<double> values = local_.stored_populations(first, count);
  if (force) {
    for (const auto& component : local_.force_density()) {
      values.insert(values.end(), component.begin() + static_cast<std::ptrdiff_t>(first),
                    component.begin() + static_cast<std::ptrdiff_t>(first + count));
    }
  }
  return values;
}

void DistributedFluid::unpack_planes(int local_z, int planes, const std::vector<double>& values,
                                     bool force) {
  const lattice::LatticeGrid& grid = local_.grid();
  const std::size_t first = grid.index(0, 0, local_z);
  const std::size_t count = static_cast<std::size_t>(planes) * grid.nx() * grid.ny();
  const std::size_t populations = lattice::kDirections * count;
  local_.replace_stored_populations(first, count,
                                    std::span<const double>(values).first(populations));
  if (force) {
    auto& density = local_.force_density();
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const auto begin = values.begin() + static_cast<std::ptrdiff_t>(populations + axis * count);
      std::copy(begin, begin + static_cast<std::ptrdiff_t>(count),
                density[axis].begin() + static_cast<std::ptrdiff_t>(first));
    }
  }
}

void DistributedFluid::exchange_full_state() {
  const auto start = std::chrono::steady_clock::now();
  const int ranks = communicator_.size();
  const int upper = (communicator_.rank() + 1) % ranks;
  const int lower = (communicator_.rank() + ranks - 1) % ranks;
  const int slab = z_end() - z_begin();
  // Once on, the force field stays on everywhere: the agreement is needed only until then.
  if (!force_in_halo_) force_in_halo_ = communicator_.any(force_field_);
  const bool force = force_in_halo_;
  // Upward: the slab's top planes become the upper neighbour's lower ghost planes.
  const std::vector<double> top = pack_planes(slab, kHaloPlanes, force);
  std::vector<double> lower_ghost(top.size());
  communicator_.send_receive(top, upper, lower_ghost, lower, kUpwardTag);
  // Downward: the slab's bottom planes become the lower neighbour's upper ghost planes.
  const std::vector<double> bottom = pack_planes(kHaloPlanes, kHaloPlanes, force);
  std::vector<double> upper_ghost(bottom.size());
  communicator_.send_receive(bottom, lower, upper_ghost, upper, kDownwardTag);
  unpack_planes(0, kHaloPlanes, lower_ghost, force);
  unpack_planes(slab + kHaloPlanes, kHaloPlanes, upper_ghost, force);
  ++counters_.exchanges;
  counters_.messages += 2;
  counters_.bytes += (top.size() + bottom.size()) * sizeof(double);
  counters_.seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void DistributedFluid::exchange_slots(int up_from, int up_to, std::span<const int> up_slots,
                                      int down_from, int down_to, std::span<const int> down_slots,
                                      const std::vector<char>* up_mask,
                                      const std::vector<char>* down_mask) {
  const auto start = std::chrono::steady_clock::now();
  const int ranks = communicator_.size();
  const int upper = (communicator_.rank() + 1) % ranks;
  const int lower = (communicator_.rank() + ranks - 1) % ranks;
  const lattice::LatticeGrid& grid = local_.grid();
  const std::size_t plane = static_cast<std::size_t>(grid.nx()) * grid.ny();
  // What the lower neighbour sends up lands here in plane up_to; what the upper one sends down,
  // in down_to.
  const std::vector<double> up =
      local_.stored_populations(grid.index(0, 0, up_from), plane, up_slots);
  std::vector<double> from_lower(up.size());
  communicator_.send_receive(up, upper, from_lower, lower, kUpwardTag);
  const std::vector<double> down =
      local_.stored_populations(grid.index(0, 0, down_from), plane, down_slots);
  std::vector<double> from_upper(down.size());
  communicator_.send_receive(down, lower, from_upper, upper, kDownwardTag);
  const auto replace = [&](int to, std::span<const int> slots, std::vector<double>& received,
                           const std::vector<char>* mask) {
    if (mask) {
      const std::vector<double> own = local_.stored_populations(grid.index(0, 0, to), plane, slots);
      for (std::size_t k = 0; k < received.size(); ++k) {
        if (!(*mask)[k]) received[k] = own[k];
      }
    }
    local_.replace_stored_populations(grid.index(0, 0, to), plane, received, slots);
  };
  replace(up_to, up_slots, from_lower, up_mask);
  replace(down_to, down_slots, from_upper, down_mask);
  ++counters_.exchanges;
  counters_.messages += 2;
  counters_.bytes += (up.size() + down.size()) * sizeof(double);
  counters_.seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void DistributedFluid::step() {
  if (scheme_ == HaloScheme::full_state) {
    exchange_full_state();
    local_.step();
    return;
  }
  if (local_.populations_natural()) {  // the AA kernel's local step: nothing crosses
    local_.step();
    return;
  }
  static const std::vector<int> up = slots_moving(+1);
  static const std::vector<int> down = slots_moving(-1);
  const int slab = z_end() - z_begin();
  const int bottom = kHaloPlanes;
  const int top = slab + kHaloPlanes - 1;
  // Swapped layout: slot opp(i) holds f*_i, so the populations moving up sit in the down slots.
  // The boundary planes' leaving populations into the neighbours' inner ghost planes.
  exchange_slots(top, bottom - 1, down, bottom, top + 1, up);
  local_.step();
  // Natural layout: what the boundary planes scattered into the inner ghost planes, back into the
  // neighbours' boundary planes.
  exchange_slots(top + 1, bottom, up, bottom - 1, top, down, &bottom_from_ghost_, &top_from_ghost_);
}

void DistributedFluid::advance(std::size_t steps) {
  for (std::size_t s = 0; s < steps; ++s) step();
}

lattice::SteadyStateResult DistributedFluid::run_to_steady_state(
    const lattice::SteadyStateCriterion& criterion) {
  const lattice::LatticeGrid& grid = local_.grid();
  // The slab's own planes, without the ghosts.
  const std::size_t begin = grid.index(0, 0, kHaloPlanes);
  const std::size_t end = grid.index(0, 0, grid.nz() - kHaloPlanes);
  lattice::VectorField previous = local_.velocity();
  return lattice::run_until_steady(
      criterion, [this](std::size_t steps) { advance(steps); },
      [&] {
        require_finite_velocity();
        const auto local = local_.velocity_change_since(previous, begin, end);
        return lattice::relative_velocity_change(
            {communicator_.max(local.change), communicator_.max(local.speed)});
      });
}

void DistributedFluid::copy_state_into(lattice::FluidSolver& whole) const {
  StateArchive gathered("the distributed fluid");
  save_state(gathered);  // on rank 0
  // The undivided solver's own arrays name what to copy and their sizes.
  StateArchive shape("the undivided fluid");
  whole.save_state(shape);
  StateArchive copied("the distributed fluid");
  for (const auto& [name, values] : shape.arrays()) {
    std::vector<double> array = communicator_.is_root() ? gathered.take(name, values.size())
                                                        : std::vector<double>(values.size());
    communicator_.broadcast_from_root(array);
    copied.put(name, std::move(array));
  }
  whole.restore_state(copied);
}

lattice::SteadyStateResult run_to_steady_state(const Communicator& communicator,
                                               lattice::FluidSolver& whole, int block_planes,
                                               const lattice::SteadyStateCriterion& criterion) {
  if (communicator.size() == 1) return whole.run_to_steady_state(criterion);
  DistributedFluid distributed(communicator, whole, block_planes);
  const auto result = distributed.run_to_steady_state(criterion);
  distributed.copy_state_into(whole);
  return result;
}

double DistributedFluid::total_mass() const {
  const lattice::LatticeGrid& grid = local_.grid();
  const int slab = z_end() - z_begin();
  std::vector<double> plane_mass(slab, 0.0);
  const std::vector<double> populations =
      local_.stored_populations(0, grid.node_count());  // as stored: shift single precision back
  const bool single = local_.parameters().precision == lattice::Precision::single_precision;
  for (int z = 0; z < slab; ++z) {
    for (int y = 0; y < grid.ny(); ++y) {
      for (int x = 0; x < grid.nx(); ++x) {
        const std::size_t node = grid.index(x, y, z + kHaloPlanes);
        if (!local_.boundaries().is_fluid(node)) continue;
        for (int i = 0; i < lattice::kDirections; ++i) {
          const double stored = populations[i * grid.node_count() + node];
          plane_mass[z] += single ? stored + lattice::kWeights[i] : stored;
        }
      }
    }
  }
  const std::vector<double> all_planes = communicator_.gather_to_root(plane_mass);
  double mass = 0.0;
  for (const double m : all_planes) mass += m;
  communicator_.broadcast_from_root(std::span<double>(&mass, 1));
  return mass;
}

std::vector<double> DistributedFluid::gather_field(std::span<const double> local,
                                                   int components) const {
  const lattice::LatticeGrid& grid = local_.grid();
  const std::size_t plane = static_cast<std::size_t>(grid.nx()) * grid.ny();
  const std::size_t own = static_cast<std::size_t>(z_end() - z_begin()) * plane;
  std::vector<double> mine;
  mine.reserve(components * own);
  for (int c = 0; c < components; ++c) {
    const auto begin =
        local.begin() + static_cast<std::ptrdiff_t>(c * grid.node_count() + kHaloPlanes * plane);
    mine.insert(mine.end(), begin, begin + static_cast<std::ptrdiff_t>(own));
  }
  const std::vector<double> gathered = communicator_.gather_to_root(mine);
  if (!communicator_.is_root()) return {};
  // Rank r's values: component c of its k-th node at [offset_r + c * count_r + k].
  const std::size_t nodes = global_.node_count();
  std::vector<double> field(components * nodes);
  std::size_t offset = 0;
  for (int rank = 0; rank < communicator_.size(); ++rank) {
    const std::size_t first = static_cast<std::size_t>(decomposition_.z_begin(rank)) * plane;
    const std::size_t count =
        static_cast<std::size_t>(decomposition_.z_end(rank) - decomposition_.z_begin(rank)) * plane;
    for (int c = 0; c < components; ++c) {
      std::copy_n(gathered.begin() + static_cast<std::ptrdiff_t>(offset + c * count), count,
                  field.begin() + static_cast<std::ptrdiff_t>(c * nodes + first));
    }
    offset += components * count;
  }
  return field;
}

std::vector<double> DistributedFluid::scatter_field(std::span<const double> global,
                                                    int components) const {
  const std::size_t plane = static_cast<std::size_t>(global_.nx()) * global_.ny();
  const std::size_t nodes = global_.node_count();
  std::vector<std::vector<double>> slices;
  if (communicator_.is_root()) {
    for (int rank = 0; rank < communicator_.size(); ++rank) {
      const int first_z = decomposition_.z_begin(rank) - kHaloPlanes;
      const int planes =
          decomposition_.z_end(rank) - decomposition_.z_begin(rank) + 2 * kHaloPlanes;
      std::vector<double> slice;
      slice.reserve(components * planes * plane);
      for (int c = 0; c < components; ++c) {
        for (int z = first_z; z < first_z + planes; ++z) {
          const auto begin =
              global.begin() + static_cast<std::ptrdiff_t>(
                                   c * nodes + lattice::LatticeGrid::wrap(z, global_.nz()) * plane);
          slice.insert(slice.end(), begin, begin + static_cast<std::ptrdiff_t>(plane));
        }
      }
      slices.push_back(std::move(slice));
    }
  }
  return communicator_.scatter_from_root(slices, components * local_.grid().node_count());
}

std::vector<double> DistributedFluid::gather_stored_populations() const {
  return gather_field(local_.stored_populations(0, local_.grid().node_count()),
                      lattice::kDirections);
}

void DistributedFluid::save_state(StateArchive& archive) const {
  StateArchive local("distributed fluid");
  local_.save_state(local);
  // Per-node arrays gathered into the undivided solver's; the rest is the same on every process.
  for (const auto& [name, values] : local.arrays()) {
    const std::size_t nodes = local_.grid().node_count();
    if (values.size() % nodes == 0 && values.size() >= nodes) {
      auto field = gather_field(values, static_cast<int>(values.size() / nodes));
      if (communicator_.is_root()) archive.put(name, std::move(field));
    } else if (communicator_.is_root()) {
      archive.put(name, values);
    }
  }
}

void DistributedFluid::restore_state(StateArchive& archive) {
  // What the local solver saves names the arrays and tells which are per node.
  StateArchive shape("distributed fluid");
  local_.save_state(shape);
  const std::size_t local_nodes = local_.grid().node_count();
  std::string problem;
  std::vector<std::pair<std::string, std::vector<double>>> taken;
  if (communicator_.is_root()) {
    try {
      for (const auto& [name, values] : shape.arrays()) {
        const bool per_node = values.size() % local_nodes == 0 && values.size() >= local_nodes;
        const std::size_t expected =
            per_node ? values.size() / local_nodes * global_.node_count() : values.size();
        taken.emplace_back(name, archive.take(name, expected));
      }
    } catch (const InputError& error) {
      problem = error.what();
    }
  }
  if (communicator_.any(!problem.empty())) {
    if (!problem.empty()) throw InputError(problem);
    throw InputError(archive.source(), "does not fit the distributed lattice (see rank 0)");
  }
  StateArchive local(archive.source());
  std::size_t k = 0;
  for (const auto& [name, values] : shape.arrays()) {
    const bool per_node = values.size() % local_nodes == 0 && values.size() >= local_nodes;
    std::vector<double> global = communicator_.is_root() ? taken[k].second : std::vector<double>();
    ++k;
    if (per_node) {
      local.put(name, scatter_field(global, static_cast<int>(values.size() / local_nodes)));
    } else {
      global.resize(values.size());
      communicator_.broadcast_from_root(global);
      local.put(name, std::move(global));
    }
  }
  local_.restore_state(local);
}

void DistributedFluid::write_checkpoint(const std::filesystem::path& file,
                                        std::string_view config_fingerprint) const {
  StateArchive archive;
  save_state(archive);
  std::string problem;
  if (communicator_.is_root()) {
    try {
      io::write_state_archive(file, archive, kFluidCheckpointVersion, config_fingerprint);
    } catch (const std::exception& error) {
      problem = error.what();
    }
  }
  if (communicator_.any(!problem.empty())) {
    throw RuntimeFailure(problem.empty() ? "checkpoint: rank 0 could not write " + file.string()
                                         : problem);
  }
}

void DistributedFluid::read_checkpoint(const std::filesystem::path& file,
                                       std::string_view config_fingerprint) {
  StateArchive archive(file.string());
  std::string problem;
  bool bad_input = false;
  if (communicator_.is_root()) {
    try {
      archive = io::read_state_archive(file, kFluidCheckpointVersion, config_fingerprint);
    } catch (const InputError& error) {
      problem = error.what();
      bad_input = true;
    } catch (const std::exception& error) {  // any failure: every process must hear of it
      problem = file.string() + ": " + error.what();
    }
  }
  if (communicator_.any(!problem.empty())) {
    const std::string message =
        problem.empty() ? file.string() + ": not read (see rank 0)" : problem;
    if (communicator_.any(bad_input)) throw InputError(message);
    throw RuntimeFailure(message);
  }
  restore_state(archive);
  if (communicator_.is_root()) {
    try {
      archive.require_all_taken();
    } catch (const InputError& error) {
      problem = error.what();
    }
  }
  if (communicator_.any(!problem.empty())) {
    throw InputError(problem.empty() ? file.string() + ": does not fit (see rank 0)" : problem);
  }
}

std::string DistributedFluid::state_sha256() const {
  const std::vector<double> populations = gather_stored_populations();
  if (!communicator_.is_root()) return {};
  return io::sha256_hex(std::as_bytes(std::span<const double>(populations)));
}

void DistributedFluid::require_finite_velocity() const {
  const lattice::LatticeGrid& grid = local_.grid();
  std::string found;
  for (int z = kHaloPlanes; z < grid.nz() - kHaloPlanes && found.empty(); ++z) {
    for (int y = 0; y < grid.ny() && found.empty(); ++y) {
      for (int x = 0; x < grid.nx() && found.empty(); ++x) {
        const std::size_t node = grid.index(x, y, z);
        if (!local_.boundaries().is_fluid(node)) continue;
        const auto u = local_.velocity_at(node);
        if (!(std::isfinite(u[0]) && std::isfinite(u[1]) && std::isfinite(u[2]))) {
          found = "lattice: non-finite fluid velocity at node (" + std::to_string(x) + ", " +
                  std::to_string(y) + ", " + std::to_string(z - kHaloPlanes + z_begin()) +
                  ") after step " + std::to_string(local_.time()) + " (process " +
                  std::to_string(communicator_.rank()) + ")";
        }
      }
    }
  }
  if (communicator_.any(!found.empty())) {
    throw RuntimeFailure(found.empty() ? "lattice: another process found a non-finite velocity"
                                       : found);
  }
}

}  // namespace rbcsim::parallel
