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
#include "parallel/distributed_fluid.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace rbcsim::parallel {

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
  std::size_t owned_point_count() const { return owned_points_.size(); }

  // Adds every point's force (lattice units) times its weights to the force density of this
  // process's own nodes.
  void spread(std::span<const Vec3> forces_lu, DistributedFluid& fluid) const;
  // Collective: every point's velocity, the same on every process.
  std::vector<Vec3> interpolate(const DistributedFluid& fluid) const;

 private:
  // The local node of global node `node` if this process holds its plane, else -1.
  std::int64_t own_local_node(std::size_t node) const;

  const DistributedFluid& fluid_;
  const ibm::DeltaKernel& kernel_;
  ibm::GridView global_grid_;
  std::vector<std::uint8_t> solid_;  // the whole lattice's, one byte per node
  ibm::InterpolationStencil stencil_;
  std::vector<std::size_t> owned_points_;
};

}  // namespace rbcsim::parallel
