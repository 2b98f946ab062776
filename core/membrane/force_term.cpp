#include "membrane/force_term.hpp"

#include <cmath>
#include <sstream>

#include "common/errors.hpp"

namespace rbcsim::membrane {

MeshStencils MeshStencils::build(std::span<const mesh::Triangle> triangles,
                                 const mesh::MeshTopology& topology) {
  const auto& edges = topology.edges();
  std::vector<std::int32_t> edge_slots;
  std::vector<std::int32_t> hinge_slots;
  for (const auto& edge : edges) {
    edge_slots.insert(edge_slots.end(), {edge.vertex0, edge.vertex1});
    hinge_slots.insert(hinge_slots.end(), {edge.vertex0, edge.vertex1, edge.wing0, edge.wing1});
  }
  std::vector<std::int32_t> triangle_slots;
  for (const auto& corners : triangles) {
    triangle_slots.insert(triangle_slots.end(), corners.begin(), corners.end());
  }
  const auto vertex_count = topology.vertex_count();
  return {VertexGather(edge_slots, vertex_count), VertexGather(triangle_slots, vertex_count),
          VertexGather(hinge_slots, vertex_count)};
}

void require_within_limit(std::string_view term, std::string_view element, double deviation,
                          double tau) {
  if (std::abs(deviation) < tau) return;
  std::ostringstream message;
  message << "membrane term '" << term << "': " << element << " has deviation d = " << deviation
          << ", at or beyond its limit tau = " << tau
          << " where the force law is singular (unstable deformation)";
  throw RuntimeFailure(message.str());
}

void set_area_gradient_slots(const TermContext& context, std::size_t t,
                             double coefficient_pN_per_um, std::span<Vec3> slot_forces_pN) {
  const auto gradients_um = triangle_area_gradients_um(
      context.positions_um, context.triangles[t], context.geometry.triangle_area_vectors_um2[t]);
  for (std::size_t k = 0; k < 3; ++k) {
    slot_forces_pN[3 * t + k] = coefficient_pN_per_um * gradients_um[k];
  }
}

void summarize_elements(std::string_view term, std::string_view element_kind,
                        std::span<const double> deviations, std::span<const double> energies_pN_um,
                        double tau, TermForces& out) {
  double energy_pN_um = 0.0;
  double max_abs_deviation = 0.0;
  for (std::size_t i = 0; i < deviations.size(); ++i) {
    // `!(|d| < tau)` also catches NaN.
    if (!(std::abs(deviations[i]) < tau)) {
      require_within_limit(term, std::string(element_kind) + " " + std::to_string(i), deviations[i],
                           tau);
    }
    energy_pN_um += energies_pN_um[i];
    max_abs_deviation = std::max(max_abs_deviation, std::abs(deviations[i]));
  }
  out.energy_pN_um = energy_pN_um;
  out.max_abs_deviation = max_abs_deviation;
}

}  // namespace rbcsim::membrane
