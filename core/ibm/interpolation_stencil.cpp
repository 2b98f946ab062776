#include "ibm/interpolation_stencil.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/errors.hpp"

namespace rbcsim::ibm {
namespace {

// Beyond this a coordinate is a runaway point, and its node number would overflow an int.
constexpr double kMaxCoordinate = 1e9;

// One axis of a point's support: each node's contribution to the stored node index (its number
// along the axis times the axis stride) and its 1D kernel weight (0 for a node outside a
// non-periodic grid).
struct AxisSupport {
  std::array<std::size_t, kMaxSupportWidth> index_offset{};
  std::array<double, kMaxSupportWidth> weight{};
};

AxisSupport axis_support(const DeltaKernel& kernel, double coordinate, int extent, bool periodic,
                         std::size_t stride) {
  AxisSupport axis;
  const int first = first_node_in_support(kernel, coordinate);
  // One modulo per axis: consecutive nodes then wrap by a subtraction (also when the periodic
  // extent is smaller than the support).
  int stored = periodic ? wrap_or_drop(first, extent, true) : first;
  for (int slot = 0; slot < kernel.support_width; ++slot, ++stored) {
    if (periodic && stored == extent) stored = 0;
    const bool exists = stored >= 0 && stored < extent;
    axis.index_offset[slot] = exists ? static_cast<std::size_t>(stored) * stride : 0;
    axis.weight[slot] = exists ? kernel.weight_1d(coordinate - (first + slot)) : 0.0;
  }
  return axis;
}

bool placeable(const Vec3& position) {
  return position.allFinite() && position.cwiseAbs().maxCoeff() < kMaxCoordinate;
}

// Fills one point's slots; returns how many nodes it kept (0: no fluid node in reach).
std::uint8_t fill_point(const DeltaKernel& kernel, const GridView& grid,
                        const std::uint8_t* solid_mask, const Vec3& position, std::size_t* nodes,
                        double* weights) {
  if (!placeable(position)) return 0;
  const auto nx = static_cast<std::size_t>(grid.nx);
  const AxisSupport x = axis_support(kernel, position.x(), grid.nx, grid.periodic_x, 1);
  const AxisSupport y = axis_support(kernel, position.y(), grid.ny, grid.periodic_y, nx);
  const AxisSupport z = axis_support(kernel, position.z(), grid.nz, grid.periodic_z,
                                     nx * static_cast<std::size_t>(grid.ny));
  const int width = kernel.support_width;
  std::uint8_t count = 0;
  double total_weight = 0.0;
  for (int c = 0; c < width; ++c) {
    for (int b = 0; b < width; ++b) {
      const double weight_yz = y.weight[b] * z.weight[c];
      if (!(weight_yz > 0.0)) continue;
      const std::size_t index_offset_yz = y.index_offset[b] + z.index_offset[c];
      for (int a = 0; a < width; ++a) {
        const double weight = x.weight[a] * weight_yz;
        if (!(weight > 0.0)) continue;
        const std::size_t node = x.index_offset[a] + index_offset_yz;
        if (solid_mask != nullptr && solid_mask[node] != 0) continue;
        nodes[count] = node;
        weights[count] = weight;
        total_weight += weight;
        ++count;
      }
    }
  }
  const double normalisation = count > 0 ? 1.0 / total_weight : 0.0;
  for (std::uint8_t slot = 0; slot < count; ++slot) weights[slot] *= normalisation;
  return count;
}

std::string unplaceable_point_message(const DeltaKernel& kernel, std::size_t point,
                                      const Vec3& position) {
  std::ostringstream message;
  message << "immersed boundary: Lagrangian point " << point << " at (" << position.x() << ", "
          << position.y() << ", " << position.z() << ") lattice units has no fluid node within the "
          << kernel.name
          << " kernel's support: it left the grid, entered a wall, or its position is not finite";
  return message.str();
}

}  // namespace

void InterpolationStencil::build(const DeltaKernel& kernel, const GridView& grid,
                                 std::span<const Vec3> positions_lu,
                                 const std::uint8_t* solid_mask) {
  if (grid.nx <= 0 || grid.ny <= 0 || grid.nz <= 0) {
    throw std::invalid_argument("InterpolationStencil::build: the grid has no nodes");
  }
  grid_ = grid;
  const auto width = static_cast<std::size_t>(kernel.support_width);
  slots_per_point_ = width * width * width;
  const std::size_t point_count = positions_lu.size();
  node_counts_.resize(point_count);
  nodes_.resize(point_count * slots_per_point_);
  weights_.resize(point_count * slots_per_point_);
  node_bounds_.resize(point_count);

#pragma omp parallel for schedule(static)
  for (std::size_t point = 0; point < point_count; ++point) {
    const std::size_t first_slot = point * slots_per_point_;
    const std::uint8_t count = fill_point(kernel, grid, solid_mask, positions_lu[point],
                                          nodes_.data() + first_slot, weights_.data() + first_slot);
    node_counts_[point] = count;
    const auto [lowest, highest] =
        std::minmax_element(nodes_.begin() + first_slot, nodes_.begin() + first_slot + count);
    node_bounds_[point] = count > 0 ? NodeIndexBounds{*lowest, *highest} : NodeIndexBounds{1, 0};
  }

  const auto unplaceable = std::ranges::find(node_counts_, std::uint8_t{0});
  if (unplaceable != node_counts_.end()) {
    const auto point = static_cast<std::size_t>(unplaceable - node_counts_.begin());
    throw RuntimeFailure(unplaceable_point_message(kernel, point, positions_lu[point]));
  }
}

}  // namespace rbcsim::ibm
