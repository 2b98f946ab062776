#include "mesh/surface_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::mesh {
namespace {

// Parameter step of the forward differences that give the map's Jacobian: the map is smooth and
// of order 1-10 um; the Jacobian only steers the relaxation (positions are always exact), so a
// relative accuracy of ~1e-7 is ample.
constexpr double kJacobianStep = 1e-7;
// A vertex moves at most this fraction of its shortest parameter-space edge per pass.
constexpr double kMaxStepPerShortestEdge = 0.25;
// A triangle whose normal turns more than 60 deg away from the surface normal at its corners
// counts as folded: the moves of its vertices in that pass are undone.
constexpr double kFoldCosine = 0.5;

struct TangentBasis {
  Vec3 first;
  Vec3 second;
};

TangentBasis tangent_basis(const Vec3& unit_direction) {
  const Vec3 helper = std::abs(unit_direction.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 first = unit_direction.cross(helper).normalized();
  return {first, unit_direction.cross(first)};
}

// The surface at one parameter point: position and the Jacobian in an orthonormal tangent basis
// (first x second = outward), so jacobian.col(0) x jacobian.col(1) is an outward normal.
struct LocalChart {
  TangentBasis basis;
  Vec3 position_um;
  Eigen::Matrix<double, 3, 2> jacobian;

  LocalChart(const SurfaceMap& surface, const Vec3& unit_direction)
      : basis(tangent_basis(unit_direction)), position_um(surface(unit_direction)) {
    auto derivative = [&](const Vec3& along) {
      return Vec3((surface((unit_direction + kJacobianStep * along).normalized()) - position_um) /
                  kJacobianStep);
    };
    jacobian.col(0) = derivative(basis.first);
    jacobian.col(1) = derivative(basis.second);
  }
  Vec3 unit_normal() const { return jacobian.col(0).cross(jacobian.col(1)).normalized(); }

  // The parameter point whose image moved by the tangential part of `displacement_um`: the
  // least-squares solution alpha of J alpha = displacement, which discards the normal component,
  // so the vertex slides along the surface.
  Vec3 slide(const Vec3& unit_direction, const Vec3& displacement_um,
             double max_parameter_step) const {
    const Eigen::Vector2d alpha = jacobian.colPivHouseholderQr().solve(displacement_um);
    Vec3 step = alpha[0] * basis.first + alpha[1] * basis.second;
    if (step.norm() > max_parameter_step) step *= max_parameter_step / step.norm();
    return (unit_direction + step).normalized();
  }
};

std::vector<Vec3> map_all(const SurfaceMap& surface, const std::vector<Vec3>& parameters) {
  std::vector<Vec3> positions(parameters.size());
  std::transform(parameters.begin(), parameters.end(), positions.begin(), surface);
  return positions;
}

struct RelaxationStep {
  std::vector<Vec3> parameters;
  std::vector<Vec3> surface_normals;  // at the parameters before the step
};

// One Jacobi pass of tangential area-weighted smoothing (Botsch & Kobbelt 2004, "A remeshing
// approach to multiresolution modeling"): each vertex slides towards the area-weighted mean of
// the centroids of its triangles. Large triangles pull their neighbours in, so triangle areas
// even out while the angles stay near 60 deg. (Springs with equal rest lengths even out the edge
// lengths faster but shear the stomatocyte's lip into slivers.)
RelaxationStep relaxation_pass(const SurfaceMap& surface, const MeshTopology& topology,
                               const std::vector<Triangle>& triangles,
                               const std::vector<Vec3>& parameters, double step_fraction) {
  const auto positions = map_all(surface, parameters);
  const auto& edge_offsets = topology.vertex_edge_offsets();
  const auto& triangle_offsets = topology.vertex_triangle_offsets();
  auto area_weighted_centroid = [&](std::size_t v) {
    Vec3 weighted_sum = Vec3::Zero();
    double area_sum = 0.0;
    for (auto k = triangle_offsets[v]; k < triangle_offsets[v + 1]; ++k) {
      const auto& triangle = triangles[topology.vertex_triangles()[k]];
      const double area = triangle_area_um2(positions, triangle);
      weighted_sum +=
          area / 3.0 * (positions[triangle[0]] + positions[triangle[1]] + positions[triangle[2]]);
      area_sum += area;
    }
    return Vec3(weighted_sum / area_sum);
  };
  RelaxationStep step{std::vector<Vec3>(parameters.size()), std::vector<Vec3>(parameters.size())};
  for (std::size_t v = 0; v < parameters.size(); ++v) {
    double shortest_parameter_edge = std::numeric_limits<double>::infinity();
    for (auto k = edge_offsets[v]; k < edge_offsets[v + 1]; ++k) {
      const auto& edge = topology.edges()[topology.vertex_edges()[k]];
      const auto other = edge.vertex0 == static_cast<std::int32_t>(v) ? edge.vertex1 : edge.vertex0;
      shortest_parameter_edge =
          std::min(shortest_parameter_edge, (parameters[other] - parameters[v]).norm());
    }
    const LocalChart chart(surface, parameters[v]);
    step.surface_normals[v] = chart.unit_normal();
    step.parameters[v] =
        chart.slide(parameters[v], step_fraction * (area_weighted_centroid(v) - positions[v]),
                    kMaxStepPerShortestEdge * shortest_parameter_edge);
  }
  return step;
}

bool is_folded(const std::vector<Vec3>& positions, const std::vector<Vec3>& surface_normals,
               const Triangle& triangle) {
  const Vec3 normal = triangle_area_vector(positions, triangle);
  const Vec3 surface_normal =
      surface_normals[triangle[0]] + surface_normals[triangle[1]] + surface_normals[triangle[2]];
  return normal.dot(surface_normal) <= kFoldCosine * normal.norm() * surface_normal.norm();
}

// Undoes the moves of the vertices of every triangle the step folded, until none is left (a
// triangle folded already before the step cannot be helped and is left as it is).
void undo_folding_moves(const SurfaceMap& surface, const std::vector<Triangle>& triangles,
                        const std::vector<Vec3>& before, RelaxationStep& step) {
  for (bool undone = true; undone;) {
    undone = false;
    const auto positions = map_all(surface, step.parameters);
    for (const auto& triangle : triangles) {
      if (!is_folded(positions, step.surface_normals, triangle)) continue;
      for (auto v : triangle) {
        if (step.parameters[v] != before[v]) {
          step.parameters[v] = before[v];
          undone = true;
        }
      }
    }
  }
}

}  // namespace

TriangleMesh relax_parameter_mesh(const SurfaceMap& surface, TriangleMesh parameter_mesh,
                                  const RelaxationSettings& relaxation) {
  const auto topology = MeshTopology::build(parameter_mesh);
  for (int pass = 0; pass < relaxation.iterations; ++pass) {
    auto step = relaxation_pass(surface, topology, parameter_mesh.triangles,
                                parameter_mesh.positions_um, relaxation.step_fraction);
    undo_folding_moves(surface, parameter_mesh.triangles, parameter_mesh.positions_um, step);
    parameter_mesh.positions_um = std::move(step.parameters);
  }
  return parameter_mesh;
}

TriangleMesh map_mesh(const SurfaceMap& surface, TriangleMesh parameter_mesh) {
  parameter_mesh.positions_um = map_all(surface, parameter_mesh.positions_um);
  return parameter_mesh;
}

TriangleMesh relaxed_parameter_icosphere(const SurfaceMap& surface, int subdivisions,
                                         const RelaxationSettings& relaxation) {
  auto parameter_mesh = relax_parameter_mesh(surface, unit_icosphere(0), relaxation);
  for (int level = 1; level <= subdivisions; ++level) {
    parameter_mesh = relax_parameter_mesh(surface, subdivide_on_sphere(parameter_mesh), relaxation);
  }
  return parameter_mesh;
}

TriangleMesh mesh_surface(const SurfaceMap& surface, int subdivisions,
                          const RelaxationSettings& relaxation) {
  return map_mesh(surface, relaxed_parameter_icosphere(surface, subdivisions, relaxation));
}

AreaVolume axisymmetric_area_volume(const SurfaceMap& surface) {
  // Composite Simpson rule; the integrands are smooth up to the poles (r -> 0 linearly).
  constexpr int kIntervals = 4000;
  const double step = std::numbers::pi / kIntervals;
  auto meridian = [&](double psi) { return surface(Vec3(std::cos(psi), 0.0, std::sin(psi))); };
  AreaVolume sums;
  for (int i = 0; i <= kIntervals; ++i) {
    const double psi = -0.5 * std::numbers::pi + i * step;
    const Vec3 point = meridian(psi);
    // Central differences here: the quadrature must be accurate to ~1e-10.
    constexpr double kStep = 1e-6;
    const Vec3 tangent = (meridian(psi + kStep) - meridian(psi - kStep)) / (2.0 * kStep);
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double radius = std::hypot(point.x(), point.y());
    sums.area_um2 += weight * 2.0 * std::numbers::pi * radius * tangent.norm();
    sums.volume_um3 += weight * std::numbers::pi * radius * radius * tangent.z();
  }
  sums.area_um2 *= step / 3.0;
  sums.volume_um3 *= step / 3.0;
  return sums;
}

}  // namespace rbcsim::mesh
