#include "ibm/transfer.hpp"

#include <omp.h>

#include <stdexcept>
#include <string>

namespace rbcsim::ibm {
namespace {

void require_stencil_fits(const InterpolationStencil& stencil, std::size_t point_count,
                          const GridView& grid, const char* caller) {
  if (stencil.grid() != grid) {
    throw std::invalid_argument(std::string(caller) + ": the stencil was built for another grid");
  }
  if (stencil.point_count() != point_count) {
    throw std::invalid_argument(std::string(caller) + ": the stencil has " +
                                std::to_string(stencil.point_count()) + " points, the data " +
                                std::to_string(point_count));
  }
}

// The calling thread's share [begin, end) of the node indices [0, node_total).
struct NodeRange {
  std::size_t begin, end;
};
NodeRange owned_nodes(std::size_t node_total) {
  const auto thread = static_cast<std::size_t>(omp_get_thread_num());
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  return {node_total * thread / threads, node_total * (thread + 1) / threads};
}

}  // namespace

void spread_forces(const InterpolationStencil& stencil, std::span<const Vec3> point_forces_lu,
                   const GridView& grid, double* fx, double* fy, double* fz) {
  const SpreadSource source{&stencil, point_forces_lu};
  spread_forces(std::span(&source, 1), grid, fx, fy, fz);
}

void spread_forces(std::span<const SpreadSource> sources, const GridView& grid, double* fx,
                   double* fy, double* fz) {
  for (const SpreadSource& source : sources) {
    require_stencil_fits(*source.stencil, source.point_forces_lu.size(), grid, "spread_forces");
  }
  const std::size_t node_total = node_count(grid);
#pragma omp parallel
  {
    const NodeRange owned = owned_nodes(node_total);
    for (const SpreadSource& source : sources) {
      const InterpolationStencil& stencil = *source.stencil;
      for (std::size_t point = 0; point < stencil.point_count(); ++point) {
        const NodeIndexBounds bounds = stencil.node_bounds(point);
        if (bounds.highest < owned.begin || bounds.lowest >= owned.end) continue;
        const auto nodes = stencil.nodes(point);
        const auto weights = stencil.weights(point);
        const Vec3& force = source.point_forces_lu[point];
        for (std::size_t slot = 0; slot < nodes.size(); ++slot) {
          const std::size_t node = nodes[slot];
          if (node < owned.begin || node >= owned.end) continue;
          fx[node] += weights[slot] * force.x();
          fy[node] += weights[slot] * force.y();
          fz[node] += weights[slot] * force.z();
        }
      }
    }
  }
}

void interpolate_velocity(const InterpolationStencil& stencil, const GridView& grid,
                          const double* ux, const double* uy, const double* uz,
                          std::span<Vec3> out_velocities_lu) {
  require_stencil_fits(stencil, out_velocities_lu.size(), grid, "interpolate_velocity");
#pragma omp parallel for schedule(static)
  for (std::size_t point = 0; point < stencil.point_count(); ++point) {
    const auto nodes = stencil.nodes(point);
    const auto weights = stencil.weights(point);
    Vec3 velocity = Vec3::Zero();
    for (std::size_t slot = 0; slot < nodes.size(); ++slot) {
      const std::size_t node = nodes[slot];
      velocity += weights[slot] * Vec3(ux[node], uy[node], uz[node]);
    }
    out_velocities_lu[point] = velocity;
  }
}

}  // namespace rbcsim::ibm
