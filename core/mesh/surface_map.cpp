#include "mesh/surface_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

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

// Finds the triangle of a unit-sphere triangulation whose cone (the rays from the origin through
// it) holds a direction, with a uniform grid over [-1, 1]^3: each triangle is filed in every cell
// its spherical cap can reach (the box of its corners grown by the cap's height above the flat
// triangle), so the cell of a direction lists every triangle that may hold it.
class SphericalTriangleLocator {
 public:
  explicit SphericalTriangleLocator(const TriangleMesh& sphere) : sphere_(sphere) {
    double longest_edge = 0.0;
    for (const auto& triangle : sphere.triangles) {
      for (int k = 0; k < 3; ++k) {
        longest_edge = std::max(longest_edge, (corner(triangle, k) - corner(triangle, (k + 1) % 3)).norm());
      }
    }
    cells_per_axis_ = std::max(1, static_cast<int>(2.0 / (2.0 * longest_edge)));
    cell_size_ = 2.0 / cells_per_axis_;
    cells_.resize(static_cast<std::size_t>(cells_per_axis_) * cells_per_axis_ * cells_per_axis_);
    for (std::size_t t = 0; t < sphere.triangles.size(); ++t) file(static_cast<std::int32_t>(t));
  }

  struct Location {
    std::int32_t triangle;
    Vec3 barycentric;  // sums to 1, each >= 0 up to round-off
  };

  Location locate(const Vec3& direction) const {
    Location best{-1, Vec3::Zero()};
    double best_smallest = -std::numeric_limits<double>::infinity();
    auto consider = [&](std::int32_t t) {
      const Vec3 weights = cone_weights(t, direction);
      const double sum = weights.sum();
      if (!(sum > 0.0)) return;  // the opposite side of the sphere
      const double smallest = weights.minCoeff() / sum;
      if (smallest > best_smallest) {
        best_smallest = smallest;
        best = {t, weights / sum};
      }
    };
    for (auto t : cells_[cell_of(direction)]) consider(t);
    // Round-off can leave a direction on an edge just outside every filed triangle: then the
    // whole mesh decides (never on a well-formed sphere in practice, but always correct).
    if (best_smallest < -kInsideTolerance) {
      for (std::size_t t = 0; t < sphere_.triangles.size(); ++t) consider(static_cast<std::int32_t>(t));
    }
    return best;
  }

 private:
  static constexpr double kInsideTolerance = 1e-9;

  const Vec3& corner(const Triangle& triangle, int k) const {
    return sphere_.positions_um[triangle[k]];
  }
  // Unnormalised barycentric coordinates of the ray through `direction` in triangle t: the
  // triple products with the opposite edges (all positive inside, for an outward triangle).
  Vec3 cone_weights(std::int32_t t, const Vec3& direction) const {
    const auto& triangle = sphere_.triangles[t];
    const Vec3& a = corner(triangle, 0);
    const Vec3& b = corner(triangle, 1);
    const Vec3& c = corner(triangle, 2);
    return {direction.dot(b.cross(c)), direction.dot(c.cross(a)), direction.dot(a.cross(b))};
  }
  int axis_cell(double coordinate) const {
    return std::clamp(static_cast<int>((coordinate + 1.0) / cell_size_), 0, cells_per_axis_ - 1);
  }
  std::size_t cell_index(int i, int j, int k) const {
    return static_cast<std::size_t>(i + cells_per_axis_ * (j + cells_per_axis_ * k));
  }
  std::size_t cell_of(const Vec3& direction) const {
    return cell_index(axis_cell(direction.x()), axis_cell(direction.y()), axis_cell(direction.z()));
  }
  void file(std::int32_t t) {
    const auto& triangle = sphere_.triangles[t];
    const Vec3& a = corner(triangle, 0);
    const Vec3 normal = (corner(triangle, 1) - a).cross(corner(triangle, 2) - a).normalized();
    const double cap_height = 1.0 - std::abs(normal.dot(a)) + kInsideTolerance;
    Vec3 low = a;
    Vec3 high = a;
    for (int k = 1; k < 3; ++k) {
      low = low.cwiseMin(corner(triangle, k));
      high = high.cwiseMax(corner(triangle, k));
    }
    const Vec3 margin = Vec3::Constant(cap_height);
    low -= margin;
    high += margin;
    for (int k = axis_cell(low.z()); k <= axis_cell(high.z()); ++k) {
      for (int j = axis_cell(low.y()); j <= axis_cell(high.y()); ++j) {
        for (int i = axis_cell(low.x()); i <= axis_cell(high.x()); ++i) {
          cells_[cell_index(i, j, k)].push_back(t);
        }
      }
    }
  }

  const TriangleMesh& sphere_;
  int cells_per_axis_ = 1;
  double cell_size_ = 2.0;
  std::vector<std::vector<std::int32_t>> cells_;
};

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

SurfaceMap piecewise_linear_map(const TriangleMesh& parameter_sphere, const TriangleMesh& surface) {
  if (parameter_sphere.triangles != surface.triangles ||
      parameter_sphere.vertex_count() != surface.vertex_count()) {
    throw std::invalid_argument("piecewise_linear_map: the meshes differ in connectivity");
  }
  constexpr double kUnitTolerance = 1e-9;
  for (const auto& point : parameter_sphere.positions_um) {
    if (std::abs(point.norm() - 1.0) > kUnitTolerance) {
      throw std::invalid_argument("piecewise_linear_map: a parameter vertex is off the unit sphere");
    }
  }
  struct State {
    TriangleMesh sphere;
    TriangleMesh surface;
    std::unique_ptr<SphericalTriangleLocator> locator;
  };
  auto state = std::make_shared<State>(State{parameter_sphere, surface, nullptr});
  state->locator = std::make_unique<SphericalTriangleLocator>(state->sphere);
  return [state](const Vec3& direction) {
    const auto [t, weights] = state->locator->locate(direction.normalized());
    const auto& triangle = state->surface.triangles[t];
    const auto& positions = state->surface.positions_um;
    return Vec3(weights[0] * positions[triangle[0]] + weights[1] * positions[triangle[1]] +
                weights[2] * positions[triangle[2]]);
  };
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
