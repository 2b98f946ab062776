#include "membrane/hinge.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"

#include "common/registry.hpp"

namespace rbcsim::membrane {
namespace {

constexpr HingeDistributionEntry kDistributions[] = {
    {"paper", distribute_as_paper},
    {"gradient", distribute_as_gradient},
};

// Outward (unnormalised) normals of triangle0 = (vertex0, vertex1, wing0) and
// triangle1 = (vertex1, vertex0, wing1); their lengths are twice the triangle areas.
std::array<Vec3, 2> hinge_normals(const Hinge& hinge) {
  const auto& [v0, v1, w0, w1] = hinge.positions_um;
  return {(v1 - v0).cross(w0 - v0), (v0 - v1).cross(w1 - v1)};
}

}  // namespace

Hinge hinge_of(std::span<const Vec3> positions_um, const mesh::Edge& edge) {
  return {{positions_um[edge.vertex0], positions_um[edge.vertex1], positions_um[edge.wing0],
           positions_um[edge.wing1]}};
}

HingeGradients hinge_gradients(const Hinge& hinge) {
  const auto& [v0, v1, w0, w1] = hinge.positions_um;
  const auto normals = hinge_normals(hinge);
  const Vec3 axis = v1 - v0;
  const double length = axis.norm();
  // -n_k / h_k with h_k = |N_k| / length: -N_k length / |N_k|^2.
  const Vec3 wing0 = -normals[0] * (length / normals[0].squaredNorm());
  const Vec3 wing1 = -normals[1] * (length / normals[1].squaredNorm());
  const double alpha0 = (w0 - v0).dot(axis) / (length * length);
  const double alpha1 = (w1 - v0).dot(axis) / (length * length);
  const Vec3 unit_axis = axis / length;
  return {{-(1.0 - alpha0) * wing0 - (1.0 - alpha1) * wing1, -alpha0 * wing0 - alpha1 * wing1,
           wing0, wing1},
          {-unit_axis, unit_axis, Vec3::Zero(), Vec3::Zero()}};
}

void distribute_as_paper(const Hinge& hinge, const HingeLoad& load, std::span<Vec3, 4> forces_pN) {
  const auto normals = hinge_normals(hinge);
  const Vec3 unit_normal0 = normals[0].normalized();
  const Vec3 unit_normal1 = normals[1].normalized();
  const double push_pN = load.paper_push_pN;
  const Vec3 edge_force_pN = 0.5 * push_pN * (unit_normal0 + unit_normal1);
  forces_pN[0] = edge_force_pN;
  forces_pN[1] = edge_force_pN;
  forces_pN[2] = -push_pN * unit_normal0;
  forces_pN[3] = -push_pN * unit_normal1;
}

void distribute_as_gradient(const Hinge& hinge, const HingeLoad& load,
                            std::span<Vec3, 4> forces_pN) {
  const auto gradients = hinge_gradients(hinge);
  for (std::size_t k = 0; k < 4; ++k) {
    forces_pN[k] = -(load.energy_per_angle_pN_um * gradients.angle_per_um[k] +
                     load.energy_per_length_pN * gradients.length[k]);
  }
}

std::span<const HingeDistributionEntry> hinge_distribution_table() { return kDistributions; }

HingeDistribution find_hinge_distribution(std::string_view name) {
  return find_entry(kDistributions, name, "membrane.distribution").distribute;
}

std::vector<std::string> distribution_names() {
  std::vector<std::string> names;
  for (const auto& entry : kDistributions) names.emplace_back(entry.name);
  names.emplace_back(kVertexDistributionName);
  return names;
}

bool is_vertex_distribution(std::string_view name) { return name == kVertexDistributionName; }

void require_known_distribution(std::string_view name) {
  const auto names = distribution_names();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string choices;
  for (const auto& known : names) choices += (choices.empty() ? "" : ", ") + known;
  throw InputError("membrane.distribution",
                   "\"" + std::string(name) + "\" is not one of " + choices);
}

}  // namespace rbcsim::membrane
