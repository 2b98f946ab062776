#include "mesh/transform.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "mesh/geometry.hpp"

namespace rbcsim::mesh {
namespace {

void scale_about(TriangleMesh& mesh, const Vec3& centre_um, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) {
    throw std::invalid_argument("mesh scale factor must be positive and finite");
  }
  for (auto& position : mesh.positions_um) position = centre_um + factor * (position - centre_um);
}

}  // namespace

Vec3 solid_centroid_um(const TriangleMesh& mesh) {
  // Sum over the tetrahedra (origin, a, b, c): signed volume det/6, centroid (a + b + c)/4.
  Vec3 weighted_sum = Vec3::Zero();
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.positions_um[t[0]];
    const Vec3& b = mesh.positions_um[t[1]];
    const Vec3& c = mesh.positions_um[t[2]];
    const double det = a.dot(b.cross(c));
    six_volume += det;
    weighted_sum += det * (a + b + c) / 4.0;
  }
  return weighted_sum / six_volume;
}

void scale_to_area(TriangleMesh& mesh, double target_area_um2) {
  scale_about(mesh, solid_centroid_um(mesh), std::sqrt(target_area_um2 / surface_area_um2(mesh)));
}

void scale_to_volume(TriangleMesh& mesh, double target_volume_um3) {
  scale_about(mesh, solid_centroid_um(mesh),
              std::cbrt(target_volume_um3 / enclosed_volume_um3(mesh)));
}

void translate_centroid_to_origin(TriangleMesh& mesh) {
  const Vec3 centroid = solid_centroid_um(mesh);
  for (auto& position : mesh.positions_um) position -= centroid;
}

Eigen::Matrix3d principal_axes(const TriangleMesh& mesh) {
  Vec3 mean = Vec3::Zero();
  for (const auto& position : mesh.positions_um) mean += position;
  mean /= static_cast<double>(mesh.vertex_count());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& position : mesh.positions_um) {
    covariance += (position - mean) * (position - mean).transpose();
  }
  // Eigenvalues come in increasing order: reverse the columns for "largest first".
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Matrix3d axes = solver.eigenvectors().rowwise().reverse();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  return axes;
}

void align_principal_axes(TriangleMesh& mesh) {
  const Vec3 centroid = solid_centroid_um(mesh);
  const Eigen::Matrix3d to_principal = principal_axes(mesh).transpose();
  for (auto& position : mesh.positions_um) {
    position = centroid + to_principal * (position - centroid);
  }
}

void round_to_single_precision(TriangleMesh& mesh) {
  for (auto& position : mesh.positions_um) {
    for (int axis = 0; axis < 3; ++axis) {
      // Through a volatile: GCC 12.2's vectorizer drops the rounding of
      // `p[axis] = static_cast<float>(p[axis])` over a vector of Vec3 at -O2 (for x and y of
      // every point; tested in tests/mesh), leaving the doubles unrounded.
      volatile float rounded = static_cast<float>(position[axis]);
      position[axis] = rounded;
    }
  }
}

}  // namespace rbcsim::mesh
