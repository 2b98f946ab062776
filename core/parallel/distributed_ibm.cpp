#include "parallel/distributed_ibm.hpp"

#include "common/errors.hpp"
#include "lattice/lattice_grid.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rbcsim::parallel {

namespace {

constexpr int kVelocityUpTag = 3;
constexpr int kVelocityDownTag = 4;

const ibm::DeltaKernel& narrow_enough(const ibm::DeltaKernel& kernel) {
  if (kernel.support_width > 2 * kHaloPlanes) {
    throw std::logic_error("parallel: the IBM kernel " + std::string(kernel.name) +
                           " reaches beyond the " + std::to_string(kHaloPlanes) + " ghost planes");
  }
  return kernel;
}

}  // namespace

DistributedImmersedBoundary::DistributedImmersedBoundary(const DistributedFluid& fluid,
                                                         std::string_view kernel)
    : fluid_(fluid), kernel_(narrow_enough(ibm::find_delta_kernel(kernel))) {
  const WallPredicate& is_wall = fluid.walls();
  const lattice::LatticeGrid& global = fluid.global_grid();
  global_grid_ = {global.nx(), global.ny(), global.nz(), true, true, true};
  solid_.assign(global.node_count(), 0);
  if (!is_wall) return;
  for (int z = 0; z < global.nz(); ++z) {
    for (int y = 0; y < global.ny(); ++y) {
      for (int x = 0; x < global.nx(); ++x) {
        if (is_wall(x, y, z)) solid_[global.index(x, y, z)] = 1;
      }
    }
  }
}

void DistributedImmersedBoundary::build(std::span<const Vec3> positions_lu) {
  stencil_.build(kernel_, global_grid_, positions_lu, solid_.data());
  owned_points_.clear();
  const int nz = global_grid_.nz;
  for (std::size_t point = 0; point < positions_lu.size(); ++point) {
    const int plane =
        lattice::LatticeGrid::wrap(static_cast<int>(std::floor(positions_lu[point].z())), nz);
    if (plane >= fluid_.z_begin() && plane < fluid_.z_end()) owned_points_.push_back(point);
  }
}

std::int64_t DistributedImmersedBoundary::own_local_node(std::size_t node) const {
  const std::size_t plane_size = static_cast<std::size_t>(global_grid_.nx) * global_grid_.ny;
  const auto z = static_cast<int>(node / plane_size);
  if (z < fluid_.z_begin() || z >= fluid_.z_end()) return -1;
  return static_cast<std::int64_t>(node % plane_size +
                                   static_cast<std::size_t>(z - fluid_.z_begin() + kHaloPlanes) *
                                       plane_size);
}

void DistributedImmersedBoundary::spread(std::span<const Vec3> forces_lu,
                                         DistributedFluid& fluid) const {
  if (forces_lu.size() != stencil_.point_count()) {
    throw std::invalid_argument("parallel: " + std::to_string(forces_lu.size()) + " forces for " +
                                std::to_string(stencil_.point_count()) + " points");
  }
  auto& force = fluid.force_density();
  double* const fx = force[0].data();
  double* const fy = force[1].data();
  double* const fz = force[2].data();
  // Point by point, slot by slot, as ibm::spread_forces adds to each node.
  for (std::size_t point = 0; point < stencil_.point_count(); ++point) {
    const auto nodes = stencil_.nodes(point);
    const auto weights = stencil_.weights(point);
    const Vec3& f = forces_lu[point];
    for (std::size_t slot = 0; slot < nodes.size(); ++slot) {
      const std::int64_t local = own_local_node(nodes[slot]);
      if (local < 0) continue;
      fx[local] += weights[slot] * f.x();
      fy[local] += weights[slot] * f.y();
      fz[local] += weights[slot] * f.z();
    }
  }
}

std::vector<Vec3> DistributedImmersedBoundary::interpolate(const DistributedFluid& fluid) const {
  const Communicator& communicator = fluid.communicator();
  const lattice::LatticeGrid& grid = fluid.local().grid();
  const lattice::VectorField& velocity = fluid.local().velocity();
  const std::size_t plane_size = static_cast<std::size_t>(grid.nx()) * grid.ny();
  const int slab = fluid.z_end() - fluid.z_begin();
  // The velocities of the neighbours' boundary planes, into a copy of this slab's ghost planes:
  // [lower ghost planes, upper ghost planes], each component after the other.
  const auto pack = [&](int first_local_z) {
    std::vector<double> values;
    for (int axis = 0; axis < 3; ++axis) {
      const auto begin =
          velocity[axis].begin() + static_cast<std::ptrdiff_t>(first_local_z * plane_size);
      values.insert(values.end(), begin,
                    begin + static_cast<std::ptrdiff_t>(kHaloPlanes * plane_size));
    }
    return values;
  };
  const int ranks = communicator.size();
  const int upper = (communicator.rank() + 1) % ranks;
  const int lower = (communicator.rank() + ranks - 1) % ranks;
  const std::vector<double> top = pack(slab);  // the slab's highest planes
  std::vector<double> lower_ghost(top.size());
  communicator.send_receive(top, upper, lower_ghost, lower, kVelocityUpTag);
  const std::vector<double> bottom = pack(kHaloPlanes);
  std::vector<double> upper_ghost(bottom.size());
  communicator.send_receive(bottom, lower, upper_ghost, upper, kVelocityDownTag);

  const auto velocity_at = [&](std::size_t node) -> Vec3 {
    const int z = static_cast<int>(node / plane_size);
    const std::size_t in_plane = node % plane_size;
    const int nz = global_grid_.nz;
    // The node's plane relative to the slab, the periodic image nearest to it.
    int offset = z - fluid.z_begin();
    if (offset < -kHaloPlanes) offset += nz;
    if (offset >= slab + kHaloPlanes) offset -= nz;
    if (offset >= 0 && offset < slab) {
      const std::size_t local = in_plane + (offset + kHaloPlanes) * plane_size;
      return Vec3(velocity[0][local], velocity[1][local], velocity[2][local]);
    }
    const bool below = offset < 0;
    const std::vector<double>& ghost = below ? lower_ghost : upper_ghost;
    const int ghost_plane = below ? offset + kHaloPlanes : offset - slab;
    if (ghost_plane < 0 || ghost_plane >= kHaloPlanes) {
      throw std::logic_error("parallel: a stencil node beyond the ghost planes");
    }
    const std::size_t at = in_plane + ghost_plane * plane_size;
    const std::size_t component = kHaloPlanes * plane_size;
    return Vec3(ghost[at], ghost[component + at], ghost[2 * component + at]);
  };
  // Each owned point as ibm::interpolate_velocity sums it: slot by slot.
  std::vector<double> mine;
  mine.reserve(4 * owned_points_.size());
  for (const std::size_t point : owned_points_) {
    const auto nodes = stencil_.nodes(point);
    const auto weights = stencil_.weights(point);
    Vec3 u = Vec3::Zero();
    for (std::size_t slot = 0; slot < nodes.size(); ++slot) {
      u += weights[slot] * velocity_at(nodes[slot]);
    }
    mine.insert(mine.end(), {static_cast<double>(point), u.x(), u.y(), u.z()});
  }
  // Copies, no sums: rank 0 puts every point's velocity in place and hands the list to all.
  const std::vector<double> gathered = communicator.gather_to_root(mine);
  std::vector<double> flat(3 * stencil_.point_count(), 0.0);
  std::string problem;
  if (communicator.is_root()) {
    if (gathered.size() != 4 * stencil_.point_count()) {
      problem = "parallel: " + std::to_string(gathered.size() / 4) + " of " +
                std::to_string(stencil_.point_count()) + " points interpolated";
    }
    for (std::size_t k = 0; k + 3 < gathered.size(); k += 4) {
      const auto point = static_cast<std::size_t>(gathered[k]);
      for (int axis = 0; axis < 3; ++axis) flat[3 * point + axis] = gathered[k + 1 + axis];
    }
  }
  if (communicator.any(!problem.empty())) {
    throw RuntimeFailure(problem.empty() ? "parallel: a point was not interpolated (see rank 0)"
                                         : problem);
  }
  communicator.broadcast_from_root(flat);
  std::vector<Vec3> velocities(stencil_.point_count());
  for (std::size_t point = 0; point < velocities.size(); ++point) {
    velocities[point] = Vec3(flat[3 * point], flat[3 * point + 1], flat[3 * point + 2]);
  }
  return velocities;
}

}  // namespace rbcsim::parallel
