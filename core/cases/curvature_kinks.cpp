#include "cases/curvature_kinks.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "membrane/force_law.hpp"
#include "membrane/hinge.hpp"
#include "membrane/vertex_patch.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::cases {
namespace {

// tan^2 of the screen's half-width: 1 % wider than the smoothing window, so that the exact angle
// (not the screen's rounding) decides every edge near its edge.
const double kScreenTangentSquared = std::pow(std::tan(1.01 * kCurvatureSmoothing_rad), 2);

// Whether an edge with these angle parts may be flatter than the smoothing width, without the
// atan2 and square root of the angle, which the fluid stretch would otherwise pay for every edge
// at every step. |theta| < w needs cos > 0 and (sin |axis|)^2 < tan^2(w) cos^2 |axis|^2. Written
// as "not beyond", so that a degenerate hinge (0 against 0; its atan2(0, 0) is 0) and a NaN
// (which the exact test keeps too) stay candidates: false only for edges certainly outside the
// window.
bool may_be_flat(const mesh::HingeAngleParts& parts) {
  if (parts.cosine < 0.0) return false;
  return !(parts.sine_times_axis * parts.sine_times_axis >
           kScreenTangentSquared * parts.cosine * parts.cosine * parts.axis_squared);
}

}  // namespace

CurvatureKinks::CurvatureKinks(const membrane::MembraneModel& model)
    : model_(model),
      active_(std::ranges::find(model.parameters().forces, "total_curvature") !=
              model.parameters().forces.end()),
      vertex_form_(membrane::is_vertex_distribution(model.parameters().distribution)) {
  patch_smoothing_um_ =
      kCurvatureSmoothing_rad * membrane::mean_reference_edge_um(model.reference()) / 2.0;
}

double CurvatureKinks::sign_push_pN(const membrane::MembraneForces& forces) const {
  const auto& parameters = model_.parameters();
  const double slope = membrane::ForceLaw::with_linear_term(parameters.tau_total_curvature)
                           .slope(forces.cell.total_curvature);
  return -parameters.k_total_curvature_kBT * parameters.thermal_energy_pN_um /
         parameters.force_length_scale_um * slope;
}

std::vector<FlatEdge> CurvatureKinks::flat_edges(std::span<const Vec3> positions_um,
                                                 const membrane::MembraneForces& forces) const {
  std::vector<FlatEdge> flat;
  if (!active_ || vertex_form_) return flat;
  const auto& parameters = model_.parameters();
  // -scale slope(d_C): the paper's F for sign +1.
  const double push_pN = sign_push_pN(forces);
  const auto distribute = membrane::find_hinge_distribution(parameters.distribution);
  for (const auto& edge : model_.topology().edges()) {
    const auto parts = mesh::hinge_angle_parts(positions_um, edge);
    if (!may_be_flat(parts)) continue;
    const double angle_rad = mesh::signed_dihedral_angle_rad(parts);
    if (std::abs(angle_rad) >= kCurvatureSmoothing_rad) continue;
    const auto hinge = membrane::hinge_of(positions_um, edge);
    const double length_um = (hinge.positions_um[1] - hinge.positions_um[0]).norm();
    const membrane::HingeLoad sign_part{push_pN, -0.5 * std::sqrt(3.0) * push_pN * length_um, 0.0};
    FlatEdge kink{{edge.vertex0, edge.vertex1, edge.wing0, edge.wing1}, {}, angle_rad};
    distribute(hinge, sign_part, kink.sign_force_pN);
    flat.push_back(kink);
  }
  return flat;
}

void CurvatureKinks::smooth(std::span<const Vec3> positions_um,
                            const membrane::MembraneForces& forces,
                            std::span<Vec3> net_forces_pN) const {
  if (active_ && vertex_form_) smooth_patches(positions_um, forces, net_forces_pN);
  for (const auto& kink : flat_edges(positions_um, forces)) {
    // sign(0) = 0, as the term itself counts a flat edge.
    const double sign = (kink.angle_rad > 0.0) - (kink.angle_rad < 0.0);
    const double weight_change = kink.angle_rad / kCurvatureSmoothing_rad - sign;
    for (std::size_t k = 0; k < 4; ++k) {
      net_forces_pN[kink.vertices[k]] += weight_change * kink.sign_force_pN[k];
    }
  }
}

void CurvatureKinks::smooth_patches(std::span<const Vec3> positions_um,
                                    const membrane::MembraneForces& forces,
                                    std::span<Vec3> net_forces_pN) const {
  const auto& topology = model_.topology();
  std::vector<Vec3> normals(topology.vertex_count());
  std::vector<double> offsets_um(topology.vertex_count());
  membrane::measure_vertex_patches(positions_um, model_.triangles(), topology, normals,
                                   offsets_um);
  const double push_pN = sign_push_pN(forces);
  // The change of each flat patch's push; zero elsewhere.
  std::vector<double> push_changes_pN(topology.vertex_count(), 0.0);
  for (std::size_t v = 0; v < topology.vertex_count(); ++v) {
    const double offset_um = offsets_um[v];
    if (std::abs(offset_um) >= patch_smoothing_um_) continue;
    const double sign = (offset_um > 0.0) - (offset_um < 0.0);
    push_changes_pN[v] = (offset_um / patch_smoothing_um_ - sign) * push_pN;
  }
  std::vector<Vec3> changes_pN(topology.vertex_count());
  membrane::gather_vertex_pushes(topology, normals, push_changes_pN, changes_pN);
  for (std::size_t v = 0; v < topology.vertex_count(); ++v) net_forces_pN[v] += changes_pN[v];
}

}  // namespace rbcsim::cases
