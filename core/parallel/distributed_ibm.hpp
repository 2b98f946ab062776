// The immersed boundary on the distributed lattice (distributed_fluid.hpp): the points' forces
// spread onto each process's own planes, and each point's velocity interpolated by the process that
// holds its plane, from its own planes and the ghost planes' velocities of its neighbours, then
// copied to every process. The same stencils (ibm/interpolation_stencil.hpp) and the same sums in
// the same order as ibm/transfer.hpp on the undivided lattice, so forces, velocities and the fluid
// stay bit-identical on any number of processes.
//
// This stage holds every point on every process (each process passes all of them, in the same
// order); cells owned whole by one process and their copies at the neighbours come next. A kernel
// wider than the ghost planes (support over 4 nodes) is refused.
#pragma once

#include "common/vec3.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"
#include "ibm/interpolation_stencil.hpp"
#include "ibm/transfer.hpp"
#include "parallel/distributed_fluid.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace rbcsim::parallel {

// Throws std::logic_error for a kernel whose support reaches beyond the ghost planes.
const ibm::DeltaKernel& require_within_ghost_planes(const ibm::DeltaKernel& kernel);

// Adds every source's forces (lattice units) times its weights to the force density of this
// process's own nodes, each node's contributions source by source, point by point, as
// ibm::spread_forces adds them on the undivided lattice. The stencils are of the whole lattice.
void spread_onto_slab(std::span<const ibm::SpreadSource> sources, DistributedFluid& fluid);

// A set of points whose velocities are wanted: their stencil (of the whole lattice) and the
// positions it was built at (lattice units, not wrapped), which say which process interpolates.
struct InterpolationSource {
  const ibm::InterpolationStencil* stencil;
  std::span<const Vec3> positions_lu;
};

// Collective: the fluid velocity at every point of every source (lattice units), the same on
// every process. The process holding plane floor(z) of a point interpolates it, slot by slot as
// ibm::interpolate_velocity, from its planes and the neighbours' planes `kernel` (the stencils')
// reaches, sent to it for this; the copies then go to every process in one collective. Throws
// RuntimeFailure on every process if a point was not interpolated, std::logic_error for a kernel
// wider than the ghost planes.
std::vector<std::vector<Vec3>> interpolate_on_slabs(std::span<const InterpolationSource> sources,
                                                    const ibm::DeltaKernel& kernel,
                                                    const DistributedFluid& fluid);

// One point set with its own stencil (rbcsim bench --ranks, tests).
class DistributedImmersedBoundary {
 public:
  // `kernel`: a name of ibm::delta_kernels(). The stencils drop the fluid's wall nodes; every
  // axis is periodic, as the fluid's. Throws rbcsim::InputError for an unknown kernel,
  // std::logic_error for one wider than the ghost planes.
  DistributedImmersedBoundary(const DistributedFluid& fluid, std::string_view kernel);

  // The stencils of every point (lattice coordinates of the whole lattice, not wrapped), and which
  // points this process interpolates. Throws RuntimeFailure as InterpolationStencil::build.
  void build(std::span<const Vec3> positions_lu);
  std::size_t point_count() const { return stencil_.point_count(); }
  std::size_t owned_point_count() const { return owned_point_count_; }

  // spread_onto_slab of the points' forces (lattice units).
  void spread(std::span<const Vec3> forces_lu, DistributedFluid& fluid) const;
  // Collective: interpolate_on_slabs of the points.
  std::vector<Vec3> interpolate(const DistributedFluid& fluid) const;

 private:
  const DistributedFluid& fluid_;
  const ibm::DeltaKernel& kernel_;
  ibm::GridView global_grid_;
  std::vector<std::uint8_t> solid_;  // the whole lattice's, one byte per node
  ibm::InterpolationStencil stencil_;
  std::vector<Vec3> positions_lu_;
  std::size_t owned_point_count_ = 0;
};

}  // namespace rbcsim::parallel
