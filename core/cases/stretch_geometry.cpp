#include "cases/stretch_geometry.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "mesh/transform.hpp"

namespace rbcsim::cases {
namespace {

// x counts as a longest (z as a shortest) axis when its vertex variance is within this fraction
// of the largest (smallest) principal variance: a discocyte generated on an icosphere has equal
// in-plane variances only up to the triangulation (and rounding); a cell with a real long axis
// differs by far more.
constexpr double kPrincipalVarianceTolerance = 1e-3;

bool already_in_principal_frame(const mesh::TriangleMesh& mesh) {
  Vec3 mean = Vec3::Zero();
  for (const auto& p : mesh.positions_um) mean += p;
  mean /= static_cast<double>(mesh.vertex_count());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : mesh.positions_um) covariance += (p - mean) * (p - mean).transpose();
  const Vec3 variances =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
          .eigenvalues();
  return covariance(0, 0) >= (1.0 - kPrincipalVarianceTolerance) * variances.maxCoeff() &&
         covariance(2, 2) <= (1.0 + kPrincipalVarianceTolerance) * variances.minCoeff();
}

}  // namespace

mesh::TriangleMesh in_stretch_frame(mesh::TriangleMesh mesh) {
  if (!already_in_principal_frame(mesh)) mesh::align_principal_axes(mesh);
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
  const auto [low, high] =
      std::minmax_element(positions_um.begin(), positions_um.end(),
                          [](const Vec3& a, const Vec3& b) { return a.y() < b.y(); });
  return high->y() - low->y();
}

}  // namespace rbcsim::cases
