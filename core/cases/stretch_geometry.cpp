#include "cases/stretch_geometry.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "mesh/transform.hpp"

namespace rbcsim::cases {
namespace {

// x counts as a longest axis when its vertex variance is within this fraction of the largest
// principal variance: a discocyte generated on an icosphere has equal in-plane variances only up
// to the triangulation (and rounding); a cell with a real long axis differs by far more.
constexpr double kLongAxisTolerance = 1e-3;

bool x_is_a_longest_axis(const mesh::TriangleMesh& mesh) {
  Vec3 mean = Vec3::Zero();
  for (const auto& p : mesh.positions_um) mean += p;
  mean /= static_cast<double>(mesh.vertex_count());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : mesh.positions_um) covariance += (p - mean) * (p - mean).transpose();
  const double largest =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
          .eigenvalues()
          .maxCoeff();
  return covariance(0, 0) >= (1.0 - kLongAxisTolerance) * largest;
}

using Point2 = Eigen::Vector2d;

double cross(const Point2& origin, const Point2& a, const Point2& b) {
  const Point2 u = a - origin;
  const Point2 v = b - origin;
  return u.x() * v.y() - u.y() * v.x();
}

// Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points.
std::vector<Point2> convex_hull(std::vector<Point2> points) {
  std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return points;
  std::vector<Point2> hull(2 * points.size());
  std::size_t size = 0;
  for (const auto& p : points) {  // lower hull
    while (size >= 2 && cross(hull[size - 2], hull[size - 1], p) <= 0) --size;
    hull[size++] = p;
  }
  const std::size_t lower_size = size + 1;
  for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {  // upper hull
    while (size >= lower_size && cross(hull[size - 2], hull[size - 1], *it) <= 0) --size;
    hull[size++] = *it;
  }
  hull.resize(size - 1);  // the last point is the first
  return hull;
}

}  // namespace

mesh::TriangleMesh in_stretch_frame(mesh::TriangleMesh mesh) {
  if (!x_is_a_longest_axis(mesh)) mesh::align_principal_axes(mesh);
  mesh::translate_centroid_to_origin(mesh);
  return mesh;
}

double axial_diameter_um(std::span<const Vec3> positions_um) {
  const auto [low, high] =
      std::minmax_element(positions_um.begin(), positions_um.end(),
                          [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); });
  return high->x() - low->x();
}

double transverse_diameter_um(std::span<const Vec3> positions_um) {
  std::vector<Point2> projected;
  projected.reserve(positions_um.size());
  for (const auto& p : positions_um) projected.emplace_back(p.y(), p.z());
  // The farthest pair of a point set lies on its convex hull: a few dozen points, all pairs.
  const auto hull = convex_hull(std::move(projected));
  double largest_squared = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    for (std::size_t j = i + 1; j < hull.size(); ++j) {
      largest_squared = std::max(largest_squared, (hull[i] - hull[j]).squaredNorm());
    }
  }
  return std::sqrt(largest_squared);
}

}  // namespace rbcsim::cases
