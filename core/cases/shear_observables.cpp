#include "cases/shear_observables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rbcsim::cases {
namespace {

Vec3 mean_position(std::span<const Vec3> positions_um) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : positions_um) sum += p;
  return sum / static_cast<double>(positions_um.size());
}

// Extent (max - min) of the projections onto `direction`.
double extent_along(std::span<const Vec3> positions_um, const Vec3& direction) {
  double low = direction.dot(positions_um.front());
  double high = low;
  for (const Vec3& p : positions_um) {
    const double projection = direction.dot(p);
    low = std::min(low, projection);
    high = std::max(high, projection);
  }
  return high - low;
}

// Per vertex, the mean of values_per_edge over the edges of its star.
std::vector<double> star_means(std::span<const double> values_per_edge,
                               const mesh::MeshTopology& topology) {
  const auto& offsets = topology.vertex_edge_offsets();
  const auto& star_edges = topology.vertex_edges();
  std::vector<double> means(topology.vertex_count(), 0.0);
  for (std::size_t v = 0; v < means.size(); ++v) {
    const auto first = static_cast<std::size_t>(offsets[v]);
    const auto last = static_cast<std::size_t>(offsets[v + 1]);
    for (std::size_t k = first; k < last; ++k) {
      means[v] += values_per_edge[static_cast<std::size_t>(star_edges[k])];
    }
    means[v] /= static_cast<double>(last - first);
  }
  return means;
}

// The vertex at the other end of `edge` from `vertex`.
std::size_t neighbour_across(const mesh::Edge& edge, std::size_t vertex) {
  const auto vertex0 = static_cast<std::size_t>(edge.vertex0);
  return vertex0 == vertex ? static_cast<std::size_t>(edge.vertex1) : vertex0;
}

// Per vertex, its value minus the mean over its one-ring neighbours (the umbrella Laplacian).
std::vector<double> minus_one_ring_means(std::span<const double> values_per_vertex,
                                         const mesh::MeshTopology& topology) {
  const auto& offsets = topology.vertex_edge_offsets();
  const auto& star_edges = topology.vertex_edges();
  const auto& edges = topology.edges();
  std::vector<double> residuals(values_per_vertex.size(), 0.0);
  for (std::size_t v = 0; v < residuals.size(); ++v) {
    const auto first = static_cast<std::size_t>(offsets[v]);
    const auto last = static_cast<std::size_t>(offsets[v + 1]);
    double ring_sum = 0.0;
    for (std::size_t k = first; k < last; ++k) {
      ring_sum +=
          values_per_vertex[neighbour_across(edges[static_cast<std::size_t>(star_edges[k])], v)];
    }
    residuals[v] = values_per_vertex[v] - ring_sum / static_cast<double>(last - first);
  }
  return residuals;
}

std::vector<double> dihedral_changes(std::span<const double> dihedral_angles_rad,
                                     std::span<const double> reference_angles_rad) {
  std::vector<double> changes(dihedral_angles_rad.size());
  for (std::size_t e = 0; e < changes.size(); ++e) {
    changes[e] = dihedral_angles_rad[e] - reference_angles_rad[e];
  }
  return changes;
}

double root_mean_square(std::span<const double> values) {
  double sum = 0.0;
  for (const double value : values) sum += value * value;
  return std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace

double largest_vertex_distance_um(std::span<const Vec3> positions_um) {
  double largest_squared = 0.0;
  for (std::size_t i = 0; i < positions_um.size(); ++i) {
    for (std::size_t j = i + 1; j < positions_um.size(); ++j) {
      largest_squared =
          std::max(largest_squared, (positions_um[i] - positions_um[j]).squaredNorm());
    }
  }
  return std::sqrt(largest_squared);
}

double in_plane_major_axis_rad(std::span<const Vec3> positions_um) {
  const Vec3 centre = mean_position(positions_um);
  double xx = 0.0, yy = 0.0, xy = 0.0;
  for (const Vec3& p : positions_um) {
    const Vec3 r = p - centre;
    xx += r.x() * r.x();
    yy += r.y() * r.y();
    xy += r.x() * r.y();
  }
  // The eigenvector of [[xx, xy], [xy, yy]] with the larger eigenvalue is at half this angle.
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  return angle <= -0.5 * std::numbers::pi ? angle + std::numbers::pi : angle;
}

ShearShape measure_shear_shape(std::span<const Vec3> positions_um) {
  ShearShape shape;
  shape.length_um = largest_vertex_distance_um(positions_um);
  const double axis = in_plane_major_axis_rad(positions_um);
  shape.inclination_deg = axis * 180.0 / std::numbers::pi;
  shape.breadth_um = extent_along(positions_um, Vec3(-std::sin(axis), std::cos(axis), 0.0));
  shape.deformation_index =
      (shape.length_um - shape.breadth_um) / (shape.length_um + shape.breadth_um);
  return shape;
}

double dihedral_change_rms_rad(std::span<const double> dihedral_angles_rad,
                               std::span<const double> reference_angles_rad) {
  if (dihedral_angles_rad.size() != reference_angles_rad.size() || dihedral_angles_rad.empty()) {
    throw std::invalid_argument("dihedral_change_rms_rad: one angle per edge in both spans");
  }
  return root_mean_square(dihedral_changes(dihedral_angles_rad, reference_angles_rad));
}

double dihedral_roughness_rad(std::span<const double> dihedral_angles_rad,
                              std::span<const double> reference_angles_rad,
                              const mesh::MeshTopology& topology) {
  const std::size_t edge_count = topology.edge_count();
  if (dihedral_angles_rad.size() != edge_count || reference_angles_rad.size() != edge_count) {
    throw std::invalid_argument("dihedral_roughness_rad: one angle per edge in both spans");
  }
  const auto changes = dihedral_changes(dihedral_angles_rad, reference_angles_rad);
  return root_mean_square(minus_one_ring_means(star_means(changes, topology), topology));
}

double in_plane_angle_rad(const Vec3& point, const Vec3& centre) {
  return std::atan2(point.y() - centre.y(), point.x() - centre.x());
}

double unwrap_angle_rad(double previous_unwrapped_rad, double angle_rad) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const double turns = std::round((previous_unwrapped_rad - angle_rad) / kTurn);
  return angle_rad + turns * kTurn;
}

AveragedShape average_shapes(std::span<const ShearShape> shapes) {
  if (shapes.empty()) throw std::invalid_argument("average_shapes: no samples");
  AveragedShape averaged;
  const auto n = static_cast<double>(shapes.size());
  double shortest_um = shapes.front().length_um;
  double longest_um = shortest_um;
  for (const ShearShape& shape : shapes) {
    averaged.mean.length_um += shape.length_um / n;
    averaged.mean.breadth_um += shape.breadth_um / n;
    averaged.mean.deformation_index += shape.deformation_index / n;
    averaged.mean.inclination_deg += shape.inclination_deg / n;
    shortest_um = std::min(shortest_um, shape.length_um);
    longest_um = std::max(longest_um, shape.length_um);
  }
  averaged.length_swing_um = longest_um - shortest_um;
  return averaged;
}

std::size_t samples_in_last_half_turn(std::span<const double> unwrapped_angles_rad) {
  if (unwrapped_angles_rad.empty()) return 0;
  const double final_rad = unwrapped_angles_rad.back();
  for (std::size_t count = 1; count < unwrapped_angles_rad.size(); ++count) {
    const double earlier_rad = unwrapped_angles_rad[unwrapped_angles_rad.size() - 1 - count];
    if (std::abs(final_rad - earlier_rad) >= std::numbers::pi) return count;
  }
  return 0;
}

double rotation_frequency_hz(std::span<const double> times_s,
                             std::span<const double> unwrapped_angles_rad) {
  const std::size_t n = times_s.size();
  if (n < 2 || unwrapped_angles_rad.size() != n) {
    throw std::invalid_argument("rotation_frequency_hz: two samples or more, one angle per time");
  }
  double mean_t = 0.0, mean_angle = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_t += times_s[i] / static_cast<double>(n);
    mean_angle += unwrapped_angles_rad[i] / static_cast<double>(n);
  }
  double covariance = 0.0, variance = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    covariance += (times_s[i] - mean_t) * (unwrapped_angles_rad[i] - mean_angle);
    variance += (times_s[i] - mean_t) * (times_s[i] - mean_t);
  }
  if (!(variance > 0.0)) throw std::invalid_argument("rotation_frequency_hz: times all equal");
  return -covariance / variance / (2.0 * std::numbers::pi);
}

}  // namespace rbcsim::cases
