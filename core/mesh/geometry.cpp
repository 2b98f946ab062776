#include "mesh/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rbcsim::mesh {

Vec3 triangle_area_vector(std::span<const Vec3> positions_um, const Triangle& triangle) {
  const Vec3& a = positions_um[triangle[0]];
  const Vec3& b = positions_um[triangle[1]];
  const Vec3& c = positions_um[triangle[2]];
  return 0.5 * (b - a).cross(c - a);
}

double triangle_area_um2(std::span<const Vec3> positions_um, const Triangle& triangle) {
  return triangle_area_vector(positions_um, triangle).norm();
}

double surface_area_um2(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& triangle : mesh.triangles)
    area += triangle_area_um2(mesh.positions_um, triangle);
  return area;
}

AreaStrain area_strain(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                       std::span<const double> reference_areas) {
  if (triangles.size() != reference_areas.size()) {
    throw std::invalid_argument("area strain: one reference area per triangle is needed");
  }
  AreaStrain strain;
  double area = 0.0;
  double reference_area = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!(reference_areas[t] > 0.0)) {
      throw std::invalid_argument("area strain: a reference area is not positive");
    }
    const double triangle_area = triangle_area_um2(positions, triangles[t]);
    area += triangle_area;
    reference_area += reference_areas[t];
    strain.max_abs_triangle_deviation =
        std::max(strain.max_abs_triangle_deviation,
                 std::abs(triangle_area - reference_areas[t]) / reference_areas[t]);
  }
  strain.total_relative_change = (area - reference_area) / reference_area;
  return strain;
}

double enclosed_volume_um3(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    six_volume +=
        mesh.positions_um[t[0]].dot(mesh.positions_um[t[1]].cross(mesh.positions_um[t[2]]));
  }
  return six_volume / 6.0;
}

double reduced_volume(double area_um2, double volume_um3) {
  return 6.0 * std::sqrt(std::numbers::pi) * volume_um3 / std::pow(area_um2, 1.5);
}

double edge_length_um(std::span<const Vec3> positions_um, const Edge& edge) {
  return (positions_um[edge.vertex1] - positions_um[edge.vertex0]).norm();
}

HingeAngleParts hinge_angle_parts(std::span<const Vec3> positions_um, const Edge& edge) {
  const Vec3& p0 = positions_um[edge.vertex0];
  const Vec3& p1 = positions_um[edge.vertex1];
  const Vec3 axis = p1 - p0;
  // Outward (unnormalised) normals of triangle0 = (p0, p1, wing0) and triangle1 = (p1, p0, wing1).
  const Vec3 normal0 = axis.cross(positions_um[edge.wing0] - p0);
  const Vec3 normal1 = (p0 - p1).cross(positions_um[edge.wing1] - p1);
  return {normal0.cross(normal1).dot(axis), normal0.dot(normal1), axis.squaredNorm()};
}

double signed_dihedral_angle_rad(const HingeAngleParts& parts) {
  // atan2 of (sin, cos) scaled by the same positive factor |n0||n1| (and |axis| for the sine).
  return std::atan2(parts.sine_times_axis / std::sqrt(parts.axis_squared), parts.cosine);
}

double signed_dihedral_angle_rad(std::span<const Vec3> positions_um, const Edge& edge) {
  return signed_dihedral_angle_rad(hinge_angle_parts(positions_um, edge));
}

CurvatureSums curvature_sums(std::span<const Vec3> positions_um, const MeshTopology& topology) {
  CurvatureSums sums;
  for (const auto& edge : topology.edges()) {
    const double curvature_um =
        0.5 * edge_length_um(positions_um, edge) * signed_dihedral_angle_rad(positions_um, edge);
    sums.signed_um += curvature_um;
    sums.absolute_um += std::abs(curvature_um);
  }
  return sums;
}

}  // namespace rbcsim::mesh
