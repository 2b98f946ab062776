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
// What interpolate_on_slabs sends per point: source, point, velocity.
constexpr std::size_t kValuesPerPoint = 5;

std::size_t plane_size_of(const lattice::LatticeGrid& grid) {
  return static_cast<std::size_t>(grid.nx()) * grid.ny();
}

// Whether this process interpolates the point at `position_lu`: it holds the point's plane.
bool interpolates_here(const DistributedFluid& fluid, const Vec3& position_lu) {
  const int plane = lattice::LatticeGrid::wrap(static_cast<int>(std::floor(position_lu.z())),
                                               fluid.global_grid().nz());
  return plane >= fluid.z_begin() && plane < fluid.z_end();
}

// The planes a stencil reaches below and above the plane floor(z) of its point: its nodes run
// from floor(z - w/2) + 1 (ibm/delta_kernels.hpp), w the kernel's support width.
int planes_below(const ibm::DeltaKernel& kernel) { return (kernel.support_width + 1) / 2 - 1; }
int planes_above(const ibm::DeltaKernel& kernel) { return (kernel.support_width + 1) / 2; }

// The velocity at any node the stencils of this slab's points reach: the slab's own, or
// (collective, at construction) the planes of the neighbours next to it, as many as the kernel
// reaches.
class SlabVelocities {
 public:
  SlabVelocities(const DistributedFluid& fluid, int below, int above)
      : fluid_(fluid),
        velocity_(fluid.local().velocity()),
        plane_size_(plane_size_of(fluid.global_grid())),
        slab_(fluid.z_end() - fluid.z_begin()),
        below_(below),
        above_(above) {
    const Communicator& communicator = fluid.communicator();
    const int ranks = communicator.size();
    const int upper = (communicator.rank() + 1) % ranks;
    const int lower = (communicator.rank() + ranks - 1) % ranks;
    if (below_ > 0) {  // the slab's highest planes go up, the lower neighbour's come in
      const std::vector<double> top = pack(kHaloPlanes + slab_ - below_, below_);
      lower_ghost_.resize(top.size());
      communicator.send_receive(top, upper, lower_ghost_, lower, kVelocityUpTag);
    }
    if (above_ > 0) {  // the slab's lowest planes go down, the upper neighbour's come in
      const std::vector<double> bottom = pack(kHaloPlanes, above_);
      upper_ghost_.resize(bottom.size());
      communicator.send_receive(bottom, lower, upper_ghost_, upper, kVelocityDownTag);
    }
  }

  Vec3 at(std::size_t node) const {
    const int z = static_cast<int>(node / plane_size_);
    const std::size_t in_plane = node % plane_size_;
    // The node's plane relative to the slab, as the image within the reach: below the slab by at
    // most below_ planes, or above it by at most above_ (either image of a plane reached from
    // both sides holds the same velocity).
    int offset = z - fluid_.z_begin();
    const int nz = fluid_.global_grid().nz();
    if (offset < -below_) offset += nz;
    if (offset >= slab_ + above_) offset -= nz;
    if (offset >= 0 && offset < slab_) {
      const std::size_t local = in_plane + (offset + kHaloPlanes) * plane_size_;
      return Vec3(velocity_[0][local], velocity_[1][local], velocity_[2][local]);
    }
    const bool is_below = offset < 0;
    const std::vector<double>& ghost = is_below ? lower_ghost_ : upper_ghost_;
    const int planes = is_below ? below_ : above_;
    const int ghost_plane = is_below ? offset + below_ : offset - slab_;
    if (ghost_plane < 0 || ghost_plane >= planes) {
      throw std::logic_error("parallel: a stencil node beyond the planes its kernel reaches");
    }
    const std::size_t at = in_plane + ghost_plane * plane_size_;
    const std::size_t component = static_cast<std::size_t>(planes) * plane_size_;
    return Vec3(ghost[at], ghost[component + at], ghost[2 * component + at]);
  }

 private:
  // `planes` planes of velocity from local plane first_local_z, each component after the other.
  std::vector<double> pack(int first_local_z, int planes) const {
    std::vector<double> values;
    for (int axis = 0; axis < 3; ++axis) {
      const auto begin =
          velocity_[axis].begin() + static_cast<std::ptrdiff_t>(first_local_z * plane_size_);
      values.insert(values.end(), begin, begin + static_cast<std::ptrdiff_t>(planes * plane_size_));
    }
    return values;
  }

  const DistributedFluid& fluid_;
  const lattice::VectorField& velocity_;
  std::size_t plane_size_;
  int slab_;
  int below_;
  int above_;
  std::vector<double> lower_ghost_;  // the planes below the slab, x, y, z one after the other
  std::vector<double> upper_ghost_;
};

}  // namespace

const ibm::DeltaKernel& require_within_ghost_planes(const ibm::DeltaKernel& kernel) {
  if (kernel.support_width > 2 * kHaloPlanes) {
    throw std::logic_error("parallel: the IBM kernel " + std::string(kernel.name) +
                           " reaches beyond the " + std::to_string(kHaloPlanes) + " ghost planes");
  }
  return kernel;
}

void spread_onto_slab(std::span<const ibm::SpreadSource> sources, DistributedFluid& fluid) {
  for (const ibm::SpreadSource& source : sources) {
    if (source.point_forces_lu.size() != source.stencil->point_count()) {
      throw std::invalid_argument("parallel: " + std::to_string(source.point_forces_lu.size()) +
                                  " forces for " + std::to_string(source.stencil->point_count()) +
                                  " points");
    }
  }
  auto& force = fluid.force_density();
  double* const fx = force[0].data();
  double* const fy = force[1].data();
  double* const fz = force[2].data();
  // Source by source, point by point, slot by slot, as ibm::spread_forces adds to each node.
  for (const ibm::SpreadSource& source : sources) {
    const ibm::InterpolationStencil& stencil = *source.stencil;
    for (std::size_t point = 0; point < stencil.point_count(); ++point) {
      const auto nodes = stencil.nodes(point);
      const auto weights = stencil.weights(point);
      const Vec3& f = source.point_forces_lu[point];
      for (std::size_t slot = 0; slot < nodes.size(); ++slot) {
        const std::int64_t local = fluid.own_local_index(nodes[slot]);
        if (local < 0) continue;
        fx[local] += weights[slot] * f.x();
        fy[local] += weights[slot] * f.y();
        fz[local] += weights[slot] * f.z();
      }
    }
  }
}

std::vector<std::vector<Vec3>> interpolate_on_slabs(std::span<const InterpolationSource> sources,
                                                    const ibm::DeltaKernel& kernel,
                                                    const DistributedFluid& fluid) {
  require_within_ghost_planes(kernel);
  const SlabVelocities velocity(fluid, planes_below(kernel), planes_above(kernel));
  std::size_t total_points = 0;
  std::vector<double> mine;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const ibm::InterpolationStencil& stencil = *sources[s].stencil;
    if (sources[s].positions_lu.size() != stencil.point_count()) {
      throw std::invalid_argument("parallel: " + std::to_string(sources[s].positions_lu.size()) +
                                  " positions for " + std::to_string(stencil.point_count()) +
                                  " points");
    }
    total_points += stencil.point_count();
    for (std::size_t point = 0; point < stencil.point_count(); ++point) {
      if (!interpolates_here(fluid, sources[s].positions_lu[point])) continue;
      const auto nodes = stencil.nodes(point);
      const auto weights = stencil.weights(point);
      Vec3 u = Vec3::Zero();
      for (std::size_t slot = 0; slot < nodes.size(); ++slot) {
        u += weights[slot] * velocity.at(nodes[slot]);
      }
      mine.insert(mine.end(),
                  {static_cast<double>(s), static_cast<double>(point), u.x(), u.y(), u.z()});
    }
  }
  // Copies, no sums: every process puts every point's velocity in place.
  const std::vector<double> gathered = fluid.communicator().gather_to_all(mine);
  if (gathered.size() != kValuesPerPoint * total_points) {  // the same on every process
    throw RuntimeFailure("parallel: " + std::to_string(gathered.size() / kValuesPerPoint) + " of " +
                         std::to_string(total_points) + " points interpolated");
  }
  std::vector<std::vector<Vec3>> velocities(sources.size());
  for (std::size_t s = 0; s < sources.size(); ++s) {
    velocities[s].assign(sources[s].stencil->point_count(), Vec3::Zero());
  }
  for (std::size_t k = 0; k < gathered.size(); k += kValuesPerPoint) {
    velocities[static_cast<std::size_t>(gathered[k])][static_cast<std::size_t>(gathered[k + 1])] =
        Vec3(gathered[k + 2], gathered[k + 3], gathered[k + 4]);
  }
  return velocities;
}

DistributedImmersedBoundary::DistributedImmersedBoundary(const DistributedFluid& fluid,
                                                         std::string_view kernel)
    : fluid_(fluid), kernel_(require_within_ghost_planes(ibm::find_delta_kernel(kernel))) {
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
  positions_lu_.assign(positions_lu.begin(), positions_lu.end());
  owned_point_count_ = 0;
  for (const Vec3& position : positions_lu_) {
    if (interpolates_here(fluid_, position)) ++owned_point_count_;
  }
}

void DistributedImmersedBoundary::spread(std::span<const Vec3> forces_lu,
                                         DistributedFluid& fluid) const {
  const ibm::SpreadSource source{&stencil_, forces_lu};
  spread_onto_slab(std::span(&source, 1), fluid);
}

std::vector<Vec3> DistributedImmersedBoundary::interpolate(const DistributedFluid& fluid) const {
  const InterpolationSource source{&stencil_, positions_lu_};
  return std::move(interpolate_on_slabs(std::span(&source, 1), kernel_, fluid).front());
}

}  // namespace rbcsim::parallel
