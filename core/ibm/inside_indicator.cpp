#include "ibm/inside_indicator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rbcsim::ibm {
namespace {

// 128-bit integers: the exact products of two snapped coordinate differences (up to 2^70).
__extension__ using Wide = __int128;

// Vertex coordinates are snapped to multiples of 2^-kSnapBits lattice spacings.
constexpr int kSnapBits = 24;
constexpr double kSnapScale = 16777216.0;  // 2^24

using Snapped = std::array<std::int64_t, 2>;

int sign_of(Wide value) { return value > 0 ? 1 : (value < 0 ? -1 : 0); }
int sign_of(std::int64_t value) { return value > 0 ? 1 : (value < 0 ? -1 : 0); }

// Twice the signed area of (a, b, p) in the xy plane, exact.
Wide orientation(const Snapped& a, const Snapped& b, const Snapped& p) {
  return static_cast<Wide>(b[0] - a[0]) * static_cast<Wide>(p[1] - a[1]) -
         static_cast<Wide>(b[1] - a[1]) * static_cast<Wide>(p[0] - a[0]);
}

// The side of the directed edge a -> b on which the column p passes once displaced by (e, e^2),
// e -> 0+: the orientation's sign when it is not zero, else the sign of its derivative
// -(b_y - a_y) e + (b_x - a_x) e^2. Antisymmetric in (a, b), so the two triangles sharing an edge
// see opposite sides and exactly one of them counts the column. 0 only for a = b (a vertical
// edge, whose triangles have no area seen along z).
int displaced_side(const Snapped& a, const Snapped& b, const Snapped& p, Wide& determinant) {
  determinant = orientation(a, b, p);
  if (determinant != 0) return sign_of(determinant);
  if (b[1] != a[1]) return sign_of(a[1] - b[1]);
  return sign_of(b[0] - a[0]);
}

// Floor and ceiling of value / 2^kSnapBits (arithmetic shifts round towards -infinity).
std::int64_t floor_unsnapped(std::int64_t value) { return value >> kSnapBits; }
std::int64_t ceil_unsnapped(std::int64_t value) { return -((-value) >> kSnapBits); }

// Squared distance from p to the triangle (a, b, c): the closest point by the Voronoi regions of
// its vertices, edges and face (Ericson, Real-Time Collision Detection, 5.1.5).
double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    return (ap - (d1 / (d1 - d3)) * ab).squaredNorm();
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    return (ap - (d2 / (d2 - d6)) * ac).squaredNorm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return (bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)).squaredNorm();
  }
  const double denominator = 1.0 / (va + vb + vc);
  return (ap - (vb * denominator) * ab - (vc * denominator) * ac).squaredNorm();
}

// Below this many box nodes a fork-join costs more than it saves.
constexpr std::size_t kThreadedBoxNodes = 4096;

// Node range [first, last] of box axis `axis` (relative to the box) covering [low, high].
std::array<int, 2> box_range(double low, double high, const NodeBox& box, int axis) {
  const int first = std::max(static_cast<int>(std::ceil(low)) - box.first[axis], 0);
  const int last =
      std::min(static_cast<int>(std::floor(high)) - box.first[axis], box.count[axis] - 1);
  return {first, last};
}

}  // namespace

double smoothed_heaviside(double distance, double half_width) {
  if (distance <= -half_width) return 0.0;
  if (distance >= half_width) return 1.0;
  const double ratio = distance / half_width;
  return 0.5 * (1.0 + ratio + std::sin(std::numbers::pi * ratio) / std::numbers::pi);
}

void SurfaceIndicator::compute(std::span<const Vec3> vertices,
                               std::span<const SurfaceTriangle> triangles, double half_width) {
  if (!(half_width > 0.0)) throw std::invalid_argument("ibm: indicator half width must be > 0");
  half_width_ = half_width;
  box_ = {};
  values_.clear();
  winding_.clear();
  if (vertices.empty()) return;
  Vec3 low = vertices.front();
  Vec3 high = low;
  for (const Vec3& vertex : vertices) {
    if (!vertex.allFinite()) throw std::invalid_argument("ibm: non-finite surface vertex");
    low = low.cwiseMin(vertex);
    high = high.cwiseMax(vertex);
  }
  for (int axis = 0; axis < 3; ++axis) {
    box_.first[axis] = static_cast<int>(std::ceil(low[axis] - half_width));
    box_.count[axis] = static_cast<int>(std::floor(high[axis] + half_width)) - box_.first[axis] + 1;
  }
  snapped_xy_.resize(vertices.size());
  vertex_z_.resize(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    snapped_xy_[v] = {static_cast<std::int64_t>(std::llround(vertices[v].x() * kSnapScale)),
                      static_cast<std::int64_t>(std::llround(vertices[v].y() * kSnapScale))};
    vertex_z_[v] = vertices[v].z();
  }
  collect_crossings(triangles);
  fill_winding_numbers();
  fill_distances(vertices, triangles);

  values_.resize(box_.node_count());
  const auto count = static_cast<std::int64_t>(values_.size());
  const double limit_squared = half_width * half_width;
#pragma omp parallel for schedule(static) if (values_.size() >= kThreadedBoxNodes)
  for (std::int64_t n = 0; n < count; ++n) {
    const bool inside = winding_[n] != 0;
    if (distance_squared_[n] >= limit_squared) {
      values_[n] = inside ? 1.0 : 0.0;
      continue;
    }
    const double distance = std::sqrt(distance_squared_[n]);
    values_[n] = smoothed_heaviside(inside ? distance : -distance, half_width);
  }
}

void SurfaceIndicator::collect_crossings(std::span<const SurfaceTriangle> triangles) {
  const int columns_x = box_.count[0];
  const std::size_t columns = static_cast<std::size_t>(columns_x) * box_.count[1];
  // The crossings in triangle order, each tagged with its column, then grouped by column.
  std::vector<std::pair<std::size_t, Crossing>>& found = found_;
  found.clear();
  for (const SurfaceTriangle& triangle : triangles) {
    const Snapped& a = snapped_xy_[triangle[0]];
    const Snapped& b = snapped_xy_[triangle[1]];
    const Snapped& c = snapped_xy_[triangle[2]];
    const int area_sign = sign_of(orientation(a, b, c));
    if (area_sign == 0) continue;  // seen edge-on from above: no column crosses it
    const auto column_range = [&](int axis) {
      const std::int64_t low = std::min({a[axis], b[axis], c[axis]});
      const std::int64_t high = std::max({a[axis], b[axis], c[axis]});
      const auto first = std::max<std::int64_t>(ceil_unsnapped(low), box_.first[axis]);
      const auto last =
          std::min<std::int64_t>(floor_unsnapped(high), box_.first[axis] + box_.count[axis] - 1);
      return std::array<int, 2>{static_cast<int>(first), static_cast<int>(last)};
    };
    const auto range_x = column_range(0);
    const auto range_y = column_range(1);
    for (int y = range_y[0]; y <= range_y[1]; ++y) {
      for (int x = range_x[0]; x <= range_x[1]; ++x) {
        const Snapped p = {static_cast<std::int64_t>(x) << kSnapBits, static_cast<std::int64_t>(y)
                                                                          << kSnapBits};
        Wide weight_a = 0;
        Wide weight_b = 0;
        Wide weight_c = 0;
        if (displaced_side(b, c, p, weight_a) != area_sign ||
            displaced_side(c, a, p, weight_b) != area_sign ||
            displaced_side(a, b, p, weight_c) != area_sign) {
          continue;
        }
        // Barycentric z of the crossing; the weights share the area's sign, so their sum is not 0.
        const double wa = static_cast<double>(weight_a);
        const double wb = static_cast<double>(weight_b);
        const double wc = static_cast<double>(weight_c);
        const double z = (wa * vertex_z_[triangle[0]] + wb * vertex_z_[triangle[1]] +
                          wc * vertex_z_[triangle[2]]) /
                         (wa + wb + wc);
        const std::size_t column = static_cast<std::size_t>(x - box_.first[0]) +
                                   static_cast<std::size_t>(columns_x) * (y - box_.first[1]);
        found.push_back({column, {z, area_sign}});
      }
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& p, const auto& q) {
    if (p.first != q.first) return p.first < q.first;
    if (p.second.z != q.second.z) return p.second.z < q.second.z;
    return p.second.step < q.second.step;
  });
  column_begin_.assign(columns + 1, 0);
  crossings_.clear();
  for (const auto& [column, crossing] : found) {
    ++column_begin_[column + 1];
    crossings_.push_back(crossing);
  }
  for (std::size_t c = 0; c < columns; ++c) column_begin_[c + 1] += column_begin_[c];
}

void SurfaceIndicator::fill_winding_numbers() {
  winding_.resize(box_.node_count());
  const std::size_t columns = static_cast<std::size_t>(box_.count[0]) * box_.count[1];
  const auto signed_columns = static_cast<std::int64_t>(columns);
  const int count_z = box_.count[2];
#pragma omp parallel for schedule(static) if (box_.node_count() >= kThreadedBoxNodes)
  for (std::int64_t column = 0; column < signed_columns; ++column) {
    // Downwards from the top: the winding number of the crossings above each node.
    std::size_t next = column_begin_[column + 1];
    std::int32_t winding = 0;
    for (int k = count_z - 1; k >= 0; --k) {
      const double z = box_.first[2] + k;
      while (next > column_begin_[column] && crossings_[next - 1].z > z) {
        winding += crossings_[--next].step;
      }
      winding_[static_cast<std::size_t>(column) + columns * k] = winding;
    }
  }
}

void SurfaceIndicator::fill_distances(std::span<const Vec3> vertices,
                                      std::span<const SurfaceTriangle> triangles) {
  const double eps = half_width_;
  distance_squared_.assign(box_.node_count(), eps * eps);
  // The triangles within eps of each z layer, in triangle order.
  const int layers = box_.count[2];
  layer_begin_.assign(static_cast<std::size_t>(layers) + 1, 0);
  const auto z_range = [&](const SurfaceTriangle& triangle) {
    const double low =
        std::min({vertex_z_[triangle[0]], vertex_z_[triangle[1]], vertex_z_[triangle[2]]});
    const double high =
        std::max({vertex_z_[triangle[0]], vertex_z_[triangle[1]], vertex_z_[triangle[2]]});
    return box_range(low - eps, high + eps, box_, 2);
  };
  for (const SurfaceTriangle& triangle : triangles) {
    const auto range = z_range(triangle);
    for (int k = range[0]; k <= range[1]; ++k) ++layer_begin_[k + 1];
  }
  for (int k = 0; k < layers; ++k) layer_begin_[k + 1] += layer_begin_[k];
  layer_triangles_.resize(layer_begin_[layers]);
  std::vector<std::size_t>& fill = layer_fill_;
  fill.assign(layer_begin_.begin(), layer_begin_.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto range = z_range(triangles[t]);
    for (int k = range[0]; k <= range[1]; ++k) {
      layer_triangles_[fill[k]++] = static_cast<std::int32_t>(t);
    }
  }

  const std::size_t layer_size = static_cast<std::size_t>(box_.count[0]) * box_.count[1];
#pragma omp parallel for schedule(static) if (box_.node_count() >= kThreadedBoxNodes)
  for (int k = 0; k < layers; ++k) {
    const double z = box_.first[2] + k;
    for (std::size_t slot = layer_begin_[k]; slot < layer_begin_[k + 1]; ++slot) {
      const SurfaceTriangle& triangle = triangles[layer_triangles_[slot]];
      const Vec3& a = vertices[triangle[0]];
      const Vec3& b = vertices[triangle[1]];
      const Vec3& c = vertices[triangle[2]];
      const Vec3 low = a.cwiseMin(b).cwiseMin(c);
      const Vec3 high = a.cwiseMax(b).cwiseMax(c);
      const auto range_x = box_range(low.x() - eps, high.x() + eps, box_, 0);
      const auto range_y = box_range(low.y() - eps, high.y() + eps, box_, 1);
      for (int j = range_y[0]; j <= range_y[1]; ++j) {
        for (int i = range_x[0]; i <= range_x[1]; ++i) {
          const Vec3 node(box_.first[0] + i, box_.first[1] + j, z);
          double& nearest = distance_squared_[layer_size * k + box_.count[0] * j + i];
          nearest = std::min(nearest, squared_distance_to_triangle(node, a, b, c));
        }
      }
    }
  }
}

bool grid_node_of(const GridView& grid, const NodeBox& box, int i, int j, int k,
                  std::size_t& node) {
  const int x = wrap_or_drop(box.first[0] + i, grid.nx, grid.periodic_x);
  const int y = wrap_or_drop(box.first[1] + j, grid.ny, grid.periodic_y);
  const int z = wrap_or_drop(box.first[2] + k, grid.nz, grid.periodic_z);
  if (x < 0 || y < 0 || z < 0) return false;
  node = node_index(grid, x, y, z);
  return true;
}

}  // namespace rbcsim::ibm
