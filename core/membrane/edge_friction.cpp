// Edge friction (edge_friction.hpp). Each vertex sums the forces of its edges in the order of the
// topology's vertex-edge lists, computing each edge's force itself: the two ends of an edge
// compute bitwise opposite forces (x_j - x_i and v_j - v_i are exact negations), so the total
// force vanishes to round-off and no scatter is needed (Mirheo loops over vertex rings the same
// way).
#include "membrane/edge_friction.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "membrane/parallel.hpp"

namespace rbcsim::membrane {
namespace {

const double kSqrt3 = std::numbers::sqrt3;

// The force on `vertex` from edge `e` at `velocities`.
Vec3 edge_force(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                const mesh::Edge& edge, std::int32_t vertex, const EdgeFrictionParameters& friction) {
  const std::int32_t other = edge.vertex0 == vertex ? edge.vertex1 : edge.vertex0;
  const Vec3 axis = (positions[vertex] - positions[other]).normalized();
  const Vec3 relative = velocities[vertex] - velocities[other];
  return -friction.tangential_pN_s_per_um * relative -
         friction.central_pN_s_per_um * relative.dot(axis) * axis;
}

Vec3 vertex_force(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                  const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                  std::size_t v) {
  const auto& offsets = network.vertex_edge_offsets;
  Vec3 sum = Vec3::Zero();
  for (auto k = offsets[v]; k < offsets[v + 1]; ++k) {
    sum += edge_force(positions, velocities, network.edges[network.vertex_edges[k]],
                      static_cast<std::int32_t>(v), friction);
  }
  return sum;
}

}  // namespace

const Registry<ViscositySplit>& viscosity_splits() {
  static const Registry<ViscositySplit> splits(
      "viscosity split",
      {{"central",
        "all of it along the edges, gamma_T = 0, gamma_C = 4 eta_m / sqrt3 (Mirheo's and "
        "dpdprops' practice: central forces, angular momentum conserved, no friction under a "
        "rigid rotation)",
        [](double eta) { return EdgeFrictionParameters{4.0 * eta / kSqrt3, 0.0}; }},
       {"fedosov",
        "gamma_C = gamma_T / 3 (Fedosov et al. 2010): gamma_T = 12 eta_m / (13 sqrt3); the "
        "tangential part also damps rigid rotations of the membrane and does not conserve "
        "angular momentum",
        [](double eta) {
          const double tangential = 12.0 * eta / (13.0 * kSqrt3);
          return EdgeFrictionParameters{tangential / 3.0, tangential};
        }}});
  return splits;
}

EdgeFrictionParameters edge_friction_for(double viscosity_Pa_s_um, std::string_view split) {
  return viscosity_splits().find(split, "membrane.viscosity_split").split(viscosity_Pa_s_um);
}

void edge_friction_forces(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                          const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                          std::span<Vec3> forces) {
  parallel_for(network.vertex_count(), [&](std::size_t v) {
    forces[v] = vertex_force(positions, velocities, network, friction, v);
  });
}

double edge_friction_power(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                           const EdgeNetwork& network, const EdgeFrictionParameters& friction) {
  double power = 0.0;
  for (const auto& edge : network.edges) {
    const Vec3 axis = (positions[edge.vertex0] - positions[edge.vertex1]).normalized();
    const Vec3 relative = velocities[edge.vertex0] - velocities[edge.vertex1];
    const double along = relative.dot(axis);
    power += friction.tangential_pN_s_per_um * relative.squaredNorm() +
             friction.central_pN_s_per_um * along * along;
  }
  return power;
}

std::vector<Vec3> edge_axes(std::span<const Vec3> positions, const EdgeNetwork& network) {
  std::vector<Vec3> axes(network.edges.size());
  for (std::size_t e = 0; e < axes.size(); ++e) {
    const auto& edge = network.edges[e];
    axes[e] = (positions[edge.vertex0] - positions[edge.vertex1]).normalized();
  }
  return axes;
}

void add_friction_resistance(std::span<const Vec3> axes, std::span<const Vec3> velocities,
                             const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                             std::span<Vec3> out) {
  if (friction.tangential_pN_s_per_um == 0.0) {
    // The central split (the default), without the tangential term's exact zero: the same sums.
    for (std::size_t e = 0; e < axes.size(); ++e) {
      const auto& edge = network.edges[e];
      const Vec3 relative = velocities[edge.vertex0] - velocities[edge.vertex1];
      const Vec3 resisted = (friction.central_pN_s_per_um * relative.dot(axes[e])) * axes[e];
      out[edge.vertex0] += resisted;
      out[edge.vertex1] -= resisted;
    }
    return;
  }
  for (std::size_t e = 0; e < axes.size(); ++e) {
    const auto& edge = network.edges[e];
    const Vec3 relative = velocities[edge.vertex0] - velocities[edge.vertex1];
    const Vec3 resisted = friction.tangential_pN_s_per_um * relative +
                          friction.central_pN_s_per_um * relative.dot(axes[e]) * axes[e];
    out[edge.vertex0] += resisted;
    out[edge.vertex1] -= resisted;
  }
}

void add_friction_diagonal(std::span<const Vec3> axes, const EdgeNetwork& network,
                           const EdgeFrictionParameters& friction,
                           std::span<Eigen::Matrix3d> blocks) {
  for (std::size_t e = 0; e < axes.size(); ++e) {
    const Eigen::Matrix3d block =
        friction.tangential_pN_s_per_um * Eigen::Matrix3d::Identity() +
        friction.central_pN_s_per_um * axes[e] * axes[e].transpose();
    blocks[network.edges[e].vertex0] += block;
    blocks[network.edges[e].vertex1] += block;
  }
}

}  // namespace rbcsim::membrane
