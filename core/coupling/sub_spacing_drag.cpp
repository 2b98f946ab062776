#include "coupling/sub_spacing_drag.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace rbcsim::coupling {

SubSpacingDrag::SubSpacingDrag(std::span<const mesh::Triangle> triangles,
                               const mesh::MeshTopology& topology)
    : measures_(triangles, topology),
      offsets_(topology.vertex_edge_offsets()),
      triangle_offsets_(topology.vertex_triangle_offsets()),
      triangles_(topology.vertex_triangles()) {
  neighbours_.reserve(topology.vertex_edges().size());
  for (std::size_t v = 0; v < topology.vertex_count(); ++v) {
    for (std::int32_t k = offsets_[v]; k < offsets_[v + 1]; ++k) {
      const mesh::Edge& edge = topology.edges()[topology.vertex_edges()[k]];
      neighbours_.push_back(static_cast<std::size_t>(edge.vertex0) == v ? edge.vertex1
                                                                        : edge.vertex0);
    }
  }
}

void SubSpacingDrag::add_velocities(std::span<const Vec3> positions, std::span<const Vec3> forces,
                                    double viscosity_sum, std::span<Vec3> velocities) {
  const std::size_t vertex_count = offsets_.size() - 1;
  if (positions.size() != vertex_count || forces.size() != vertex_count ||
      velocities.size() != vertex_count) {
    throw std::invalid_argument("SubSpacingDrag: " + std::to_string(positions.size()) +
                                " positions, " + std::to_string(forces.size()) + " forces and " +
                                std::to_string(velocities.size()) + " velocities for " +
                                std::to_string(vertex_count) + " vertices");
  }
  if (!(viscosity_sum > 0.0)) {
    throw std::invalid_argument("SubSpacingDrag: the viscosity sum must be positive, not " +
                                std::to_string(viscosity_sum));
  }
  measures_.measure_area_and_volume(positions);
  const auto& area_vectors = measures_.geometry.triangle_area_vectors_um2;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    Vec3 normal = Vec3::Zero();
    double triangle_area_sum = 0.0;
    for (std::int32_t k = triangle_offsets_[v]; k < triangle_offsets_[v + 1]; ++k) {
      normal += area_vectors[triangles_[k]];
      triangle_area_sum += measures_.triangle_areas_um2[triangles_[k]];
    }
    normal.normalize();
    Vec3 mean_force = Vec3::Zero();
    double mean_length = 0.0;
    for (std::int32_t k = offsets_[v]; k < offsets_[v + 1]; ++k) {
      const auto neighbour = static_cast<std::size_t>(neighbours_[k]);
      mean_force += forces[neighbour];
      mean_length += (positions[neighbour] - positions[v]).norm();
    }
    const double count = offsets_[v + 1] - offsets_[v];
    mean_force /= count;
    mean_length /= count;
    // Along the membrane at 1 / ((eta_out + eta_in) q A), along its normal at half that.
    const Vec3 unshared = forces[v] - mean_force;
    const double normal_part = normal.dot(unshared);
    const double wavenumber = std::numbers::pi / mean_length;
    const double vertex_area = triangle_area_sum / 3.0;
    velocities[v] +=
        (unshared - 0.5 * normal_part * normal) / (viscosity_sum * wavenumber * vertex_area);
  }
}

double fastest_drag_rate(SubSpacingDrag& drag, std::span<const Vec3> positions,
                         const ForceFunction& forces_at, double viscosity_sum) {
  const std::size_t count = positions.size();
  std::vector<Vec3> rest_forces(count), forces(count), displaced(count), velocities(count);
  forces_at(positions, rest_forces);
  // A sub-spacing pattern to start from: the drag's answer to random forces.
  std::mt19937 random(20261207);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (Vec3& f : forces) f = Vec3(normal(random), normal(random), normal(random));
  std::vector<Vec3> direction(count, Vec3::Zero());
  drag.add_velocities(positions, forces, viscosity_sum, direction);
  // Displacements of 1e-5 of the mean edge-like scale keep the forces linear in them.
  double scale = 0.0;
  for (std::size_t v = 1; v < count; ++v) scale += (positions[v] - positions[v - 1]).norm();
  const double step = 1e-5 * scale / static_cast<double>(count);
  double rate = 0.0;
  constexpr int kIterations = 30;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    double norm = 0.0;
    for (const Vec3& d : direction) norm = std::max(norm, d.norm());
    if (!(norm > 0.0)) return 0.0;
    for (std::size_t v = 0; v < count; ++v) {
      direction[v] /= norm;
      displaced[v] = positions[v] + step * direction[v];
    }
    forces_at(displaced, forces);
    for (std::size_t v = 0; v < count; ++v) forces[v] = (forces[v] - rest_forces[v]) / step;
    std::fill(velocities.begin(), velocities.end(), Vec3::Zero());
    drag.add_velocities(positions, forces, viscosity_sum, velocities);
    // The forces restore: the velocities point against the displacement, at `rate` times it.
    rate = 0.0;
    for (const Vec3& u : velocities) rate = std::max(rate, u.norm());
    for (std::size_t v = 0; v < count; ++v) direction[v] = -velocities[v];
  }
  return rate;
}

}  // namespace rbcsim::coupling
