#include "cases/curvature_kinks.hpp"

#include <algorithm>
#include <cmath>

#include "membrane/force_law.hpp"
#include "membrane/hinge.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::cases {
namespace {

// Projected Gauss-Seidel sweeps per call. The least-squares problem is poorly conditioned on
// flattened bands (neighbouring g_j are nearly parallel), so solving it exactly every iteration
// would cost many sweeps; instead the weights carry over from call to call and keep improving
// while the relaxation proceeds. Any weights inside their intervals give an element of the
// eps-subdifferential, so the net force is always a valid (upper) convergence measure.
constexpr int kSweepsPerCall = 2;

KinkEdge kink_edge(const mesh::Edge& edge, double angle_rad) {
  const double slack = std::abs(angle_rad) > 0.0
                           ? std::min(2.0, kCurvatureSlack_rad / std::abs(angle_rad))
                           : 2.0;
  KinkEdge kink{{edge.vertex0, edge.vertex1, edge.wing0, edge.wing1}, {}, 1.0, 1.0 - slack, 1.0};
  if (angle_rad < 0.0) {
    kink.weight = -1.0;
    kink.lowest_weight = -1.0;
    kink.highest_weight = -1.0 + slack;
  }
  return kink;
}

// Moves the edge's weight and the net force with it.
void set_weight(KinkEdge& kink, double weight, std::span<Vec3> net_forces_pN) {
  for (std::size_t k = 0; k < 4; ++k) {
    net_forces_pN[kink.vertices[k]] += (weight - kink.weight) * kink.sign_force_pN[k];
  }
  kink.weight = weight;
}

}  // namespace

CurvatureKinks::CurvatureKinks(const membrane::MembraneModel& model)
    : model_(model),
      active_(std::ranges::find(model.parameters().forces, "total_curvature") !=
              model.parameters().forces.end()) {}

std::vector<KinkEdge> CurvatureKinks::kink_edges(std::span<const Vec3> positions_um,
                                                 const membrane::MembraneForces& forces) const {
  std::vector<KinkEdge> kinks;
  if (!active_) return kinks;
  const auto& parameters = model_.parameters();
  const double slope = membrane::ForceLaw::with_linear_term(parameters.tau_total_curvature)
                           .slope(forces.cell.total_curvature);
  const double scale_pN = parameters.k_total_curvature_kBT * parameters.thermal_energy_pN_um /
                          parameters.force_length_scale_um;
  const auto distribute = membrane::find_hinge_distribution(parameters.distribution);
  const auto& edges = model_.topology().edges();
  kinks.resize(edges.size());
  const auto count = static_cast<std::ptrdiff_t>(edges.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t e = 0; e < count; ++e) {
    const auto& edge = edges[e];
    auto& kink = kinks[e];
    kink = kink_edge(edge, mesh::signed_dihedral_angle_rad(positions_um, edge));
    const auto hinge = membrane::hinge_of(positions_um, edge);
    const double length_um = (hinge.positions_um[1] - hinge.positions_um[0]).norm();
    const membrane::HingeLoad sign_part{-scale_pN * slope,
                                        0.5 * std::sqrt(3.0) * scale_pN * slope * length_um, 0.0};
    distribute(hinge, sign_part, kink.sign_force_pN);
  }
  return kinks;
}

void CurvatureKinks::to_minimal_force(std::span<const Vec3> positions_um,
                                      const membrane::MembraneForces& forces,
                                      std::span<Vec3> net_forces_pN) {
  auto kinks = kink_edges(positions_um, forces);
  if (previous_weights_.size() == kinks.size()) {
    for (std::size_t j = 0; j < kinks.size(); ++j) {
      set_weight(kinks[j], std::clamp(previous_weights_[j], kinks[j].lowest_weight,
                                      kinks[j].highest_weight),
                 net_forces_pN);
    }
  }
  // Per edge, the exact minimiser of |net force|^2 along g_j, clamped to the weight interval.
  for (int sweep = 0; sweep < kSweepsPerCall; ++sweep) {
    for (auto& kink : kinks) {
      double along_pN2 = 0.0;
      double norm_squared_pN2 = 0.0;
      for (std::size_t k = 0; k < 4; ++k) {
        along_pN2 += kink.sign_force_pN[k].dot(net_forces_pN[kink.vertices[k]]);
        norm_squared_pN2 += kink.sign_force_pN[k].squaredNorm();
      }
      if (norm_squared_pN2 == 0.0) continue;
      const double weight = std::clamp(kink.weight - along_pN2 / norm_squared_pN2,
                                       kink.lowest_weight, kink.highest_weight);
      set_weight(kink, weight, net_forces_pN);
    }
  }
  previous_weights_.resize(kinks.size());
  for (std::size_t j = 0; j < kinks.size(); ++j) previous_weights_[j] = kinks[j].weight;
}

}  // namespace rbcsim::cases
