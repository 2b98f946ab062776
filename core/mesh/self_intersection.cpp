#include "mesh/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace rbcsim::mesh {
namespace {

// Segment p0-p1 against triangle (a, b, c), Moeller-Trumbore: true when the segment's interior
// meets the triangle's interior (parallel segments and touching end points do not count).
bool segment_crosses_triangle(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  const Vec3 direction = p1 - p0;
  const Vec3 edge1 = b - a;
  const Vec3 edge2 = c - a;
  const Vec3 h = direction.cross(edge2);
  const double determinant = edge1.dot(h);
  const double scale = direction.norm() * edge1.norm() * edge2.norm();
  if (std::abs(determinant) <= 1e-12 * scale) return false;
  const double inverse = 1.0 / determinant;
  const Vec3 s = p0 - a;
  const double u = inverse * s.dot(h);
  if (u <= 0.0 || u >= 1.0) return false;
  const Vec3 q = s.cross(edge1);
  const double v = inverse * direction.dot(q);
  if (v <= 0.0 || u + v >= 1.0) return false;
  const double t = inverse * edge2.dot(q);
  return t > 0.0 && t < 1.0;
}

bool triangles_cross(const std::array<Vec3, 3>& first, const std::array<Vec3, 3>& second) {
  for (int k = 0; k < 3; ++k) {
    if (segment_crosses_triangle(first[k], first[(k + 1) % 3], second[0], second[1], second[2]) ||
        segment_crosses_triangle(second[k], second[(k + 1) % 3], first[0], first[1], first[2])) {
      return true;
    }
  }
  return false;
}

bool share_a_vertex(const Triangle& a, const Triangle& b) {
  for (auto u : a) {
    for (auto v : b) {
      if (u == v) return true;
    }
  }
  return false;
}

struct Box {
  Vec3 low;
  Vec3 high;
  bool overlaps(const Box& other) const {
    return (low.array() <= other.high.array()).all() && (other.low.array() <= high.array()).all();
  }
};

}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> self_intersections(const TriangleMesh& mesh) {
  const auto count = mesh.triangle_count();
  std::vector<std::pair<std::size_t, std::size_t>> found;
  if (count == 0) return found;
  std::vector<Box> boxes(count);
  double edge_sum = 0.0;
  Vec3 origin = mesh.positions_um.front();
  for (const auto& p : mesh.positions_um) origin = origin.cwiseMin(p);
  for (std::size_t t = 0; t < count; ++t) {
    const auto& corners = mesh.triangles[t];
    Box box{mesh.positions_um[corners[0]], mesh.positions_um[corners[0]]};
    for (int k = 1; k < 3; ++k) {
      box.low = box.low.cwiseMin(mesh.positions_um[corners[k]]);
      box.high = box.high.cwiseMax(mesh.positions_um[corners[k]]);
    }
    boxes[t] = box;
    edge_sum += (mesh.positions_um[corners[1]] - mesh.positions_um[corners[0]]).norm();
  }
  const double cell = std::max(edge_sum / static_cast<double>(count), 1e-12);
  // Each triangle is listed in every grid cell its box touches; pairs meet in a shared cell.
  auto key = [](long i, long j, long k) {
    return (i * 73856093L) ^ (j * 19349663L) ^ (k * 83492791L);
  };
  std::unordered_map<long, std::vector<std::size_t>> grid;
  auto cell_range = [&](const Box& box) {
    std::array<long, 6> range{};
    for (int axis = 0; axis < 3; ++axis) {
      range[axis] = static_cast<long>(std::floor((box.low[axis] - origin[axis]) / cell));
      range[axis + 3] = static_cast<long>(std::floor((box.high[axis] - origin[axis]) / cell));
    }
    return range;
  };
  for (std::size_t t = 0; t < count; ++t) {
    const auto r = cell_range(boxes[t]);
    for (long i = r[0]; i <= r[3]; ++i) {
      for (long j = r[1]; j <= r[4]; ++j) {
        for (long k = r[2]; k <= r[5]; ++k) grid[key(i, j, k)].push_back(t);
      }
    }
  }
  for (const auto& entry : grid) {
    const auto& members = entry.second;
    for (std::size_t a = 0; a < members.size(); ++a) {
      for (std::size_t b = a + 1; b < members.size(); ++b) {
        const auto first = std::min(members[a], members[b]);
        const auto second = std::max(members[a], members[b]);
        if (!boxes[first].overlaps(boxes[second])) continue;
        const auto& ta = mesh.triangles[first];
        const auto& tb = mesh.triangles[second];
        if (share_a_vertex(ta, tb)) continue;
        const std::array<Vec3, 3> pa{mesh.positions_um[ta[0]], mesh.positions_um[ta[1]],
                                     mesh.positions_um[ta[2]]};
        const std::array<Vec3, 3> pb{mesh.positions_um[tb[0]], mesh.positions_um[tb[1]],
                                     mesh.positions_um[tb[2]]};
        if (triangles_cross(pa, pb)) found.emplace_back(first, second);
      }
    }
  }
  // A pair sharing several grid cells (or a hash collision) is found more than once.
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

}  // namespace rbcsim::mesh
