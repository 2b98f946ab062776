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

// One axis of a point's support: the stored node numbers (-1 = outside a non-periodic grid, with
// weight 0) and their 1D kernel weights.
struct AxisSupport {
  std::array<int, kMaxSupportWidth> node{};
  std::array<double, kMaxSupportWidth> weight{};
};

AxisSupport axis_support(const DeltaKernel& kernel, double coordinate, int extent, bool periodic) {
  AxisSupport axis;
  const int first = first_node_in_support(kernel, coordinate);
  for (int slot = 0; slot < kernel.support_width; ++slot) {
    const int n = first + slot;
    axis.node[slot] = wrap_or_drop(n, extent, periodic);
    axis.weight[slot] = axis.node[slot] < 0 ? 0.0 : kernel.weight_1d(coordinate - n);
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
  std::array<AxisSupport, 3> axes;
  for (int axis = 0; axis < 3; ++axis) {
    axes[axis] =
        axis_support(kernel, position[axis], axis_extent(grid, axis), axis_periodic(grid, axis));
  }
  const int width = kernel.support_width;
  std::uint8_t count = 0;
  double total_weight = 0.0;
  for (int c = 0; c < width; ++c) {
    for (int b = 0; b < width; ++b) {
      for (int a = 0; a < width; ++a) {
        const double weight = axes[0].weight[a] * axes[1].weight[b] * axes[2].weight[c];
        if (!(weight > 0.0)) continue;
        const std::size_t node =
            node_index(grid, axes[0].node[a], axes[1].node[b], axes[2].node[c]);
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

#pragma omp parallel for schedule(static)
  for (std::size_t point = 0; point < point_count; ++point) {
    const std::size_t first_slot = point * slots_per_point_;
    node_counts_[point] = fill_point(kernel, grid, solid_mask, positions_lu[point],
                                     nodes_.data() + first_slot, weights_.data() + first_slot);
  }

  const auto unplaceable = std::ranges::find(node_counts_, std::uint8_t{0});
  if (unplaceable != node_counts_.end()) {
    const auto point = static_cast<std::size_t>(unplaceable - node_counts_.begin());
    throw RuntimeFailure(unplaceable_point_message(kernel, point, positions_lu[point]));
  }
}

}  // namespace rbcsim::ibm
