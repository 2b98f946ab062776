#include "ibm/reference_transfer.hpp"

#include <optional>

#include "common/errors.hpp"

namespace rbcsim::ibm::reference {
namespace {

// The stored index of lattice node (i, j, k) if it exists and is fluid.
std::optional<std::size_t> fluid_node(const GridView& grid, const std::uint8_t* solid_mask, int i,
                                      int j, int k) {
  const int wrapped_i = wrap_or_drop(i, grid.nx, grid.periodic_x);
  const int wrapped_j = wrap_or_drop(j, grid.ny, grid.periodic_y);
  const int wrapped_k = wrap_or_drop(k, grid.nz, grid.periodic_z);
  if (wrapped_i < 0 || wrapped_j < 0 || wrapped_k < 0) return std::nullopt;
  const std::size_t node = node_index(grid, wrapped_i, wrapped_j, wrapped_k);
  if (solid_mask != nullptr && solid_mask[node] != 0) return std::nullopt;
  return node;
}

// Calls visit(node, weight) for each fluid node in the point's support box, with the kernel
// weights divided by their sum over those nodes.
template <typename Visit>
void for_each_weighted_node(const DeltaKernel& kernel, const GridView& grid,
                            const std::uint8_t* solid_mask, const Vec3& position, Visit visit) {
  const int width = kernel.support_width;
  const int first_i = first_node_in_support(kernel, position.x());
  const int first_j = first_node_in_support(kernel, position.y());
  const int first_k = first_node_in_support(kernel, position.z());
  const auto for_each_fluid_node = [&](auto act) {
    for (int k = first_k; k < first_k + width; ++k) {
      for (int j = first_j; j < first_j + width; ++j) {
        for (int i = first_i; i < first_i + width; ++i) {
          if (const auto node = fluid_node(grid, solid_mask, i, j, k)) {
            act(*node, weight_3d(kernel, position - Vec3(i, j, k)));
          }
        }
      }
    }
  };
  double total_weight = 0.0;
  for_each_fluid_node([&](std::size_t, double weight) { total_weight += weight; });
  if (!(total_weight > 0.0)) {
    throw RuntimeFailure("reference IBM: a Lagrangian point has no fluid node in reach");
  }
  for_each_fluid_node([&](std::size_t node, double weight) { visit(node, weight / total_weight); });
}

}  // namespace

void spread_forces(const DeltaKernel& kernel, const GridView& grid, const std::uint8_t* solid_mask,
                   std::span<const Vec3> positions_lu, std::span<const Vec3> point_forces_lu,
                   double* fx, double* fy, double* fz) {
  for (std::size_t point = 0; point < positions_lu.size(); ++point) {
    const Vec3& force = point_forces_lu[point];
    for_each_weighted_node(kernel, grid, solid_mask, positions_lu[point],
                           [&](std::size_t node, double weight) {
                             fx[node] += weight * force.x();
                             fy[node] += weight * force.y();
                             fz[node] += weight * force.z();
                           });
  }
}

void interpolate_velocity(const DeltaKernel& kernel, const GridView& grid,
                          const std::uint8_t* solid_mask, std::span<const Vec3> positions_lu,
                          const double* ux, const double* uy, const double* uz,
                          std::span<Vec3> out_velocities_lu) {
  for (std::size_t point = 0; point < positions_lu.size(); ++point) {
    Vec3 velocity = Vec3::Zero();
    for_each_weighted_node(kernel, grid, solid_mask, positions_lu[point],
                           [&](std::size_t node, double weight) {
                             velocity += weight * Vec3(ux[node], uy[node], uz[node]);
                           });
    out_velocities_lu[point] = velocity;
  }
}

}  // namespace rbcsim::ibm::reference
