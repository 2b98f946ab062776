// The nodes and weights that couple each Lagrangian point (membrane vertex) to the lattice,
// computed ONCE per step and shared by force spreading and velocity interpolation
// (docs/architecture.md, one coupled step: steps 2 and 4), so both use the same operator and
// spreading is the adjoint of interpolation.
//
// Positions are in lattice spacings, node (i, j, k) at (i, j, k) (see grid_view.hpp). A point's
// nodes are the support_width^3 box its kernel reaches, less:
//  - on a periodic axis, nothing: node indices wrap around (also for a point outside the box);
//  - on a non-periodic axis, the nodes outside the grid;
//  - the nodes the solid mask marks solid (1 = solid);
//  - nodes of zero weight.
// The remaining weights are renormalised to sum to 1 (always, which also removes the kernels'
// round-off in their partition of unity). This keeps interpolation of a uniform field exact next
// to walls and the grid's edges, and makes the spread force add up to the point force exactly
// (to round-off): no momentum is put into solid nodes or lost outside the grid.
//
// Storage is compact and fixed: support_width^3 slots per point (at most 64), with a count per
// point; rebuilding for the same number of points and kernel allocates nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"

namespace rbcsim::ibm {

// The smallest and largest stored node index of one point's stencil, so that a thread spreading
// onto a range of nodes can skip whole points.
struct NodeIndexBounds {
  std::size_t lowest, highest;
};

class InterpolationStencil {
 public:
  // Computes every point's nodes and weights. `solid_mask` (one byte per node, 1 = solid) may be
  // null: no solid nodes. Throws RuntimeFailure naming the first point that has no fluid node in
  // its support (it left a non-periodic grid, entered a wall, or its position is not finite): such
  // a point can neither spread its force nor be moved. Throws std::invalid_argument for an empty
  // grid.
  void build(const DeltaKernel& kernel, const GridView& grid, std::span<const Vec3> positions_lu,
             const std::uint8_t* solid_mask = nullptr);

  std::size_t point_count() const { return node_counts_.size(); }
  const GridView& grid() const { return grid_; }
  std::span<const std::size_t> nodes(std::size_t point) const {
    return {nodes_.data() + point * slots_per_point_, node_counts_[point]};
  }
  std::span<const double> weights(std::size_t point) const {
    return {weights_.data() + point * slots_per_point_, node_counts_[point]};
  }
  NodeIndexBounds node_bounds(std::size_t point) const { return node_bounds_[point]; }

 private:
  GridView grid_{};
  std::size_t slots_per_point_ = 0;
  std::vector<std::uint8_t> node_counts_;
  std::vector<std::size_t> nodes_;
  std::vector<double> weights_;
  std::vector<NodeIndexBounds> node_bounds_;
};

}  // namespace rbcsim::ibm
