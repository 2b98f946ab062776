#include "cases/curvature_kinks.hpp"

#include <algorithm>
#include <cmath>

#include "membrane/force_law.hpp"
#include "membrane/hinge.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::cases {

CurvatureKinks::CurvatureKinks(const membrane::MembraneModel& model)
    : model_(model),
      // The vertex form's kinks (sign(M_i) at a flat patch) are not smoothed: it is a
      // reproduction variant, run in the dynamics (docs/physics.md, "The vertex form").
      active_(std::ranges::find(model.parameters().forces, "total_curvature") !=
                  model.parameters().forces.end() &&
              !membrane::is_vertex_distribution(model.parameters().distribution)) {}

std::vector<FlatEdge> CurvatureKinks::flat_edges(std::span<const Vec3> positions_um,
                                                 const membrane::MembraneForces& forces) const {
  std::vector<FlatEdge> flat;
  if (!active_) return flat;
  const auto& parameters = model_.parameters();
  const double slope = membrane::ForceLaw::with_linear_term(parameters.tau_total_curvature)
                           .slope(forces.cell.total_curvature);
  const double scale_pN = parameters.k_total_curvature_kBT * parameters.thermal_energy_pN_um /
                          parameters.force_length_scale_um;
  const auto distribute = membrane::find_hinge_distribution(parameters.distribution);
  for (const auto& edge : model_.topology().edges()) {
    const double angle_rad = mesh::signed_dihedral_angle_rad(positions_um, edge);
    if (std::abs(angle_rad) >= kCurvatureSmoothing_rad) continue;
    const auto hinge = membrane::hinge_of(positions_um, edge);
    const double length_um = (hinge.positions_um[1] - hinge.positions_um[0]).norm();
    const membrane::HingeLoad sign_part{-scale_pN * slope,
                                        0.5 * std::sqrt(3.0) * scale_pN * slope * length_um, 0.0};
    FlatEdge kink{{edge.vertex0, edge.vertex1, edge.wing0, edge.wing1}, {}, angle_rad};
    distribute(hinge, sign_part, kink.sign_force_pN);
    flat.push_back(kink);
  }
  return flat;
}

void CurvatureKinks::smooth(std::span<const Vec3> positions_um,
                            const membrane::MembraneForces& forces,
                            std::span<Vec3> net_forces_pN) const {
  for (const auto& kink : flat_edges(positions_um, forces)) {
    // sign(0) = 0, as the term itself counts a flat edge.
    const double sign = (kink.angle_rad > 0.0) - (kink.angle_rad < 0.0);
    const double weight_change = kink.angle_rad / kCurvatureSmoothing_rad - sign;
    for (std::size_t k = 0; k < 4; ++k) {
      net_forces_pN[kink.vertices[k]] += weight_change * kink.sign_force_pN[k];
    }
  }
}

}  // namespace rbcsim::cases
