// The inside indicator of a closed surface on the lattice (docs/physics.md, "Cytoplasm viscosity"):
// H = 1 at the nodes well inside a cell, 0 well outside, smoothed over the IBM kernel's half width
// eps across the membrane with the signed-distance Heaviside
//
//   H(d) = 1/2 [1 + d/eps + sin(pi d/eps)/pi]  for |d| < eps,   d > 0 inside,
//
// d the distance to the nearest triangle. H is continuous in space, and in time as the surface
// moves (a sharp 0/1 mask would flicker as nodes change sides).
//
// Inside or outside: a ray along +z from every node, the winding number of the triangles it
// crosses (+1 where the outward normal points up, -1 where it points down), one lattice column at
// a time. Exact: vertex coordinates are snapped to multiples of 2^-24 lattice spacings and the
// orientation of a column against a projected edge is an exact integer determinant; a column
// exactly through an edge or a vertex is decided by simulation of simplicity (the column displaced
// by (e, e^2) in (x, y), infinitesimally), so every column crosses a closed surface a whole number
// of times, never twice or not at all through a shared edge or vertex.
//
// Pure: lattice units, no grid state, no I/O. Deterministic and thread-count independent: every
// output node is written by one thread (columns for the winding number, z layers for the
// distances, a node's minimum distance taken over its triangles, which is order-independent).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/vec3.hpp"
#include "ibm/grid_view.hpp"

namespace rbcsim::ibm {

// Corner indices, counter-clockwise seen from outside (mesh/triangle_mesh.hpp's convention).
using SurfaceTriangle = std::array<std::int32_t, 3>;

// The nodes first[a] .. first[a] + count[a] - 1 along each axis a, in lattice coordinates that
// are not wrapped (a cell's vertices are never wrapped either).
struct NodeBox {
  std::array<int, 3> first = {0, 0, 0};
  std::array<int, 3> count = {0, 0, 0};

  std::size_t node_count() const {
    return static_cast<std::size_t>(count[0]) * static_cast<std::size_t>(count[1]) *
           static_cast<std::size_t>(count[2]);
  }
};

// The signed-distance Heaviside above, for d in lattice spacings.
double smoothed_heaviside(double distance, double half_width);

// The indicator of one surface on every node that can see a value above 0: the nodes within eps
// of its bounding box. Holds its work arrays, so that recomputing it every step allocates nothing
// once the sizes have settled.
class SurfaceIndicator {
 public:
  // `vertices` in lattice units (node (i, j, k) at (i, j, k)), `triangles` a closed, consistently
  // oriented surface over them, `half_width` eps > 0 (the IBM kernel's support / 2). An inward
  // orientation gives the same field (any nonzero winding number is inside).
  void compute(std::span<const Vec3> vertices, std::span<const SurfaceTriangle> triangles,
               double half_width);

  const NodeBox& box() const { return box_; }
  // H per node of box(), x fastest: index i + count_x (j + count_y k) for the node
  // (first_x + i, first_y + j, first_z + k).
  std::span<const double> values() const { return values_; }
  // The integer winding number of the sharp surface per node of box(), same order.
  std::span<const std::int32_t> winding_numbers() const { return winding_; }

 private:
  struct Crossing {
    double z;
    std::int32_t step;  // +1 or -1
  };
  void collect_crossings(std::span<const SurfaceTriangle> triangles);
  void fill_winding_numbers();
  void fill_distances(std::span<const Vec3> vertices, std::span<const SurfaceTriangle> triangles);

  NodeBox box_;
  double half_width_ = 1.0;
  std::vector<std::array<std::int64_t, 2>> snapped_xy_;  // per vertex, units of 2^-24
  std::vector<double> vertex_z_;
  std::vector<std::pair<std::size_t, Crossing>> found_;  // (column, crossing) as found
  std::vector<std::size_t> column_begin_;  // crossings of column c: [begin[c], begin[c + 1])
  std::vector<Crossing> crossings_;
  std::vector<std::size_t> layer_begin_;  // triangles near z layer k: [begin[k], begin[k + 1])
  std::vector<std::int32_t> layer_triangles_;
  std::vector<std::size_t> layer_fill_;
  std::vector<std::int32_t> winding_;
  std::vector<double> distance_squared_;
  std::vector<double> values_;
};

// The node of `grid` that box node (i, j, k) stands for (wrapped along periodic axes), or no node
// (false) when it lies beyond a non-periodic face.
bool grid_node_of(const GridView& grid, const NodeBox& box, int i, int j, int k, std::size_t& node);

}  // namespace rbcsim::ibm
