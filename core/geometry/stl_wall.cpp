#include "geometry/stl_wall.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "common/errors.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::geometry {
namespace {

struct EdgeSide {
  double determinant;  // twice the signed area of (u, v, ray) in the (y, z) plane
  int sign;            // its sign after the symbolic displacement of the ray; 0: degenerate edge
};

// Which side of the projected edge u -> v the ray (y, z) passes, the ray being displaced by
// (epsilon, epsilon^2) when it lies exactly on the edge's line (see stl_wall.hpp). Evaluated with
// the lower-numbered vertex first so that both triangles of an edge get exactly opposite answers.
EdgeSide side_of_edge(const Vec3& u, std::int32_t u_index, const Vec3& v, std::int32_t v_index,
                      double y_um, double z_um) {
  if (u_index > v_index) {
    const auto reversed = side_of_edge(v, v_index, u, u_index, y_um, z_um);
    return {-reversed.determinant, -reversed.sign};
  }
  const double dy = v.y() - u.y();
  const double dz = v.z() - u.z();
  const double determinant = dy * (z_um - u.z()) - dz * (y_um - u.y());
  if (determinant != 0.0) return {determinant, determinant > 0.0 ? 1 : -1};
  // d(determinant) = -dz * epsilon + dy * epsilon^2 for the displaced ray.
  if (dz != 0.0) return {0.0, dz < 0.0 ? 1 : -1};
  if (dy != 0.0) return {0.0, dy > 0.0 ? 1 : -1};
  return {0.0, 0};  // the edge is parallel to x: its triangles have no area seen along the ray
}

void require_valid_surface(const mesh::TriangleMesh& wall_mesh, std::string_view source) {
  const std::string where(source);
  if (wall_mesh.triangle_count() == 0) throw InputError(where, "the wall surface has no triangles");
  for (const auto& position : wall_mesh.positions_um) {
    if (!position.allFinite()) throw InputError(where, "a wall vertex has a non-finite coordinate");
  }
  try {
    mesh::MeshTopology::build(wall_mesh);
  } catch (const std::invalid_argument& defect) {
    throw InputError(where, std::string("the wall surface must be closed: ") + defect.what());
  }
}

FluidBounds bounding_box(const mesh::TriangleMesh& wall_mesh, std::array<bool, 3> open_axes) {
  FluidBounds bounds{wall_mesh.positions_um.front(), wall_mesh.positions_um.front(), open_axes};
  for (const auto& position : wall_mesh.positions_um) {
    bounds.min_um = bounds.min_um.cwiseMin(position);
    bounds.max_um = bounds.max_um.cwiseMax(position);
  }
  return bounds;
}

}  // namespace

StlWall::StlWall(mesh::TriangleMesh wall_mesh, std::array<bool, 3> open_axes,
                 std::string_view source)
    : mesh_(std::move(wall_mesh)) {
  require_valid_surface(mesh_, source);
  bounds_ = bounding_box(mesh_, open_axes);
  build_buckets();
}

void StlWall::build_buckets() {
  const double extent_y_um = bounds_.max_um.y() - bounds_.min_um.y();
  const double extent_z_um = bounds_.max_um.z() - bounds_.min_um.z();
  // About one bucket per triangle; never so fine that a bucket grid explodes for a flat mesh.
  const double per_triangle_um =
      std::sqrt(extent_y_um * extent_z_um / static_cast<double>(mesh_.triangle_count()));
  bucket_size_um_ = std::max(per_triangle_um, std::max(extent_y_um, extent_z_um) / 1024.0);
  if (bucket_size_um_ <= 0.0) bucket_size_um_ = 1.0;  // every vertex on one x-parallel line
  buckets_y_ = static_cast<int>(extent_y_um / bucket_size_um_) + 1;
  buckets_z_ = static_cast<int>(extent_z_um / bucket_size_um_) + 1;

  std::vector<std::pair<std::size_t, std::int32_t>> bucket_triangle_pairs;
  for (std::size_t t = 0; t < mesh_.triangle_count(); ++t) {
    Vec3 low = mesh_.positions_um[mesh_.triangles[t][0]];
    Vec3 high = low;
    for (const auto corner : mesh_.triangles[t]) {
      low = low.cwiseMin(mesh_.positions_um[corner]);
      high = high.cwiseMax(mesh_.positions_um[corner]);
    }
    // The bucket index is monotonic in y and z, so a ray inside the triangle's box lands in one
    // of the buckets listed here, boundaries included.
    const std::size_t first = bucket_of(low.y(), low.z());
    const std::size_t last = bucket_of(high.y(), high.z());
    const auto first_y = static_cast<int>(first % buckets_y_);
    const auto last_y = static_cast<int>(last % buckets_y_);
    for (std::size_t row = first / buckets_y_; row <= last / buckets_y_; ++row) {
      for (int column = first_y; column <= last_y; ++column) {
        bucket_triangle_pairs.emplace_back(row * buckets_y_ + column, static_cast<std::int32_t>(t));
      }
    }
  }
  std::sort(bucket_triangle_pairs.begin(), bucket_triangle_pairs.end());
  const auto bucket_count = static_cast<std::size_t>(buckets_y_) * buckets_z_;
  bucket_offsets_.assign(bucket_count + 1, 0);
  bucket_triangles_.clear();
  for (const auto& [bucket, triangle] : bucket_triangle_pairs) {
    ++bucket_offsets_[bucket + 1];
    bucket_triangles_.push_back(triangle);
  }
  for (std::size_t b = 0; b < bucket_count; ++b) bucket_offsets_[b + 1] += bucket_offsets_[b];
}

std::size_t StlWall::bucket_of(double y_um, double z_um) const {
  const auto clamped = [this](double offset_um, int count) {
    const double cell = std::floor(offset_um / bucket_size_um_);
    return static_cast<std::size_t>(std::clamp(cell, 0.0, static_cast<double>(count - 1)));
  };
  return clamped(y_um - bounds_.min_um.y(), buckets_y_) +
         static_cast<std::size_t>(buckets_y_) * clamped(z_um - bounds_.min_um.z(), buckets_z_);
}

void StlWall::collect_crossings(double y_um, double z_um, std::vector<Crossing>& crossings) const {
  crossings.clear();
  if (y_um < bounds_.min_um.y() || y_um > bounds_.max_um.y() || z_um < bounds_.min_um.z() ||
      z_um > bounds_.max_um.z()) {
    return;
  }
  const std::size_t bucket = bucket_of(y_um, z_um);
  for (auto slot = bucket_offsets_[bucket]; slot < bucket_offsets_[bucket + 1]; ++slot) {
    const auto& corners = mesh_.triangles[bucket_triangles_[slot]];
    const Vec3& a = mesh_.positions_um[corners[0]];
    const Vec3& b = mesh_.positions_um[corners[1]];
    const Vec3& c = mesh_.positions_um[corners[2]];
    const auto opposite_c = side_of_edge(a, corners[0], b, corners[1], y_um, z_um);
    const auto opposite_a = side_of_edge(b, corners[1], c, corners[2], y_um, z_um);
    const auto opposite_b = side_of_edge(c, corners[2], a, corners[0], y_um, z_um);
    const int sign = opposite_c.sign;
    if (sign == 0 || opposite_a.sign != sign || opposite_b.sign != sign) continue;
    // Barycentric interpolation of x; the weights share the sign, so their sum is not zero.
    const double total = opposite_a.determinant + opposite_b.determinant + opposite_c.determinant;
    const double x_um = (opposite_a.determinant * a.x() + opposite_b.determinant * b.x() +
                         opposite_c.determinant * c.x()) /
                        total;
    // sign = sign of the normal's x component: a face seen from -x is entered (+1).
    crossings.push_back({x_um, -sign});
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& p, const Crossing& q) { return p.x_um < q.x_um; });
}

bool StlWall::is_fluid(const Vec3& point_um) const {
  // A row of one node at the point.
  std::array<std::uint8_t, 1> solid{};
  classify_row(LatticeGrid{point_um, 1.0, 1, 1, 1}, 0, 0, solid);
  return solid[0] == kFluid;
}

void StlWall::classify_row(const LatticeGrid& grid, int j, int k,
                           std::span<std::uint8_t> solid_row) const {
  std::vector<Crossing> crossings;
  const Vec3 row_start_um = grid.node_position_um(0, j, k);
  collect_crossings(row_start_um.y(), row_start_um.z(), crossings);
  int winding = 0;
  std::size_t next = 0;
  for (int i = 0; i < grid.nx; ++i) {
    const double x_um = grid.node_position_um(i, j, k).x();
    while (next < crossings.size() && crossings[next].x_um < x_um) {
      winding += crossings[next++].winding_step;
    }
    solid_row[i] = winding != 0 ? kFluid : kSolid;
  }
}

}  // namespace rbcsim::geometry
