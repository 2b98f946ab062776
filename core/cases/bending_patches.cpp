#include "cases/bending_patches.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "membrane/force_terms.hpp"
#include "membrane/hinge.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::cases {
namespace {

constexpr double kJoulePerPicoNewtonMicrometre = 1e-18;

// The flat pair of edge a in z = 0 (outward +z) with both wings turned down by fold/2: a ridge,
// theta = fold. Vertices: vertex0, vertex1 (the hinge), wing0, wing1, as mesh::Edge{0,1,2,3,0,1}.
std::vector<Vec3> folded_pair(double edge_um, double fold_rad) {
  const double height_um = std::sqrt(3.0) / 2.0 * edge_um;
  const double half = fold_rad / 2.0;
  return {Vec3(0, 0, 0), Vec3(edge_um, 0, 0),
          Vec3(edge_um / 2, height_um * std::cos(half), -height_um * std::sin(half)),
          Vec3(edge_um / 2, -height_um * std::cos(half), -height_um * std::sin(half))};
}

// The moment about the hinge axis (vertex0 -> vertex1) of the bending force on wing0, pN um.
double wing_moment_pN_um(const membrane::MembraneParameters& parameters, double edge_um,
                         double fold_rad) {
  const auto positions = folded_pair(edge_um, fold_rad);
  const mesh::Edge edge{0, 1, 2, 3, 0, 1};
  const double theta_rad = mesh::signed_dihedral_angle_rad(positions, edge);  // theta0 = 0
  const auto distribution = membrane::find_hinge_distribution(parameters.distribution);
  const membrane::BendingTerm term(parameters, distribution);
  std::array<Vec3, 4> forces_pN;
  distribution(membrane::hinge_of(positions, edge), term.load_for_deviation(theta_rad), forces_pN);
  const Vec3 axis = (positions[1] - positions[0]).normalized();
  return (positions[2] - positions[0]).cross(forces_pN[2]).dot(axis);
}

// Sum of the angle terms' energies per term with every dihedral angle of the cell changed by
// `delta_rad`. The shape stays the cell's; the reference moves by -delta instead (the energies
// depend on theta - theta0 and on S - S0 only, with |S0| as the normaliser).
class UniformCurvatureMode {
 public:
  UniformCurvatureMode(const mesh::TriangleMesh& cell,
                       const membrane::MembraneParameters& parameters)
      : cell_(cell), parameters_(parameters), topology_(mesh::MeshTopology::build(cell)) {
    // The cell-level terms only where membrane.forces has them: a switched-off term adds nothing
    // to the cell's bending modulus (and its reference need not suit it, e.g. DeltaA0 ~ 0).
    parameters_.forces = {"bend"};
    for (const std::string term : {"area_difference", "total_curvature"}) {
      if (std::find(parameters.forces.begin(), parameters.forces.end(), term) !=
          parameters.forces.end()) {
        parameters_.forces.push_back(term);
      }
    }
    parameters_.vertex_force_cap_pN = INFINITY;
    rest_ = membrane::capture_reference_state(cell.positions_um, cell.triangles, topology_);
    for (std::size_t e = 0; e < topology_.edge_count(); ++e) {
      const double length_um = rest_.edge_lengths_um[e];
      const double angle_rad = rest_.dihedral_angles_rad[e];
      total_length_um_ += length_um;
      // d|theta| = sign(theta) dtheta (a flat edge, theta exactly 0, has no direction).
      signed_length_um_ += angle_rad > 0.0 ? length_um : (angle_rad < 0.0 ? -length_um : 0.0);
    }
  }

  UniformCurvatureStiffness energies(double delta_rad) const {
    auto reference = rest_;
    for (auto& angle_rad : reference.dihedral_angles_rad) angle_rad -= delta_rad;
    // S = sum l theta / 2 grows by total_length delta / 2, C / 2 D0 by signed_length delta / 2.
    reference.signed_curvature_sum_um -= total_length_um_ * delta_rad / 2.0;
    reference.absolute_curvature_sum_um -= signed_length_um_ * delta_rad / 2.0;
    const membrane::MembraneModel model(cell_, std::move(reference), parameters_);
    auto workspace = model.make_workspace();
    auto forces = model.make_forces();
    model.compute(cell_.positions_um, workspace, forces);
    const auto energy_pN_um = [&](std::string_view term) {
      const auto enabled = model.enabled_term_names();
      return std::find(enabled.begin(), enabled.end(), term) == enabled.end()
                 ? 0.0
                 : forces.term(term).energy_pN_um;
    };
    return {energy_pN_um("bend"), energy_pN_um("area_difference"), energy_pN_um("total_curvature")};
  }

 private:
  const mesh::TriangleMesh& cell_;
  membrane::MembraneParameters parameters_;
  mesh::MeshTopology topology_;
  membrane::ReferenceState rest_;
  double total_length_um_ = 0.0;
  double signed_length_um_ = 0.0;
};

}  // namespace

TwoTrianglePatchMeasurement measure_two_triangle_patch(
    const membrane::MembraneParameters& parameters, double edge_um, double angle_rad) {
  // Central difference. A positive fold turns wing0 (at +y) down about +x; the restoring force
  // pushes it back up: a positive moment about +x, growing with the fold.
  const double moment_per_angle_pN_um = (wing_moment_pN_um(parameters, edge_um, angle_rad) -
                                         wing_moment_pN_um(parameters, edge_um, -angle_rad)) /
                                        (2.0 * angle_rad);
  TwoTrianglePatchMeasurement measurement;
  measurement.moment_per_angle_pN_um = moment_per_angle_pN_um;
  // Each centroid lies h/3 from the hinge, h = (sqrt 3 / 2) a.
  measurement.hinge_distance_um = 2.0 * (std::sqrt(3.0) / 2.0 * edge_um) / 3.0;
  measurement.bending_modulus_J = moment_per_angle_pN_um / edge_um * measurement.hinge_distance_um *
                                  kJoulePerPicoNewtonMicrometre;
  return measurement;
}

double analytic_two_triangle_bending_modulus_J(const membrane::MembraneParameters& parameters,
                                               double edge_um) {
  const double tau = parameters.tau_bend_rad;
  const double arm_ratio =
      parameters.distribution == "paper" ? edge_um / parameters.force_length_scale_um : 1.0;
  return parameters.k_bend_kBT * parameters.thermal_energy_pN_um * (1.0 + 1.0 / (tau * tau)) / 2.0 *
         arm_ratio * kJoulePerPicoNewtonMicrometre;
}

UniformCurvatureStiffness measure_uniform_curvature_stiffness(
    const mesh::TriangleMesh& cell, const membrane::MembraneParameters& parameters,
    double angle_rad) {
  const UniformCurvatureMode mode(cell, parameters);
  const auto plus = mode.energies(angle_rad);
  const auto minus = mode.energies(-angle_rad);
  // Every energy is zero at the reference: E'' = (E(+) + E(-) - 2 E(0)) / delta^2.
  const double squared = angle_rad * angle_rad;
  return {(plus.bend_pN_um + minus.bend_pN_um) / squared,
          (plus.area_difference_pN_um + minus.area_difference_pN_um) / squared,
          (plus.total_curvature_pN_um + minus.total_curvature_pN_um) / squared};
}

double overall_bending_modulus_J(double unit_bending_modulus_J,
                                 const UniformCurvatureStiffness& unit_stiffness, double k_bend_kBT,
                                 double k_area_difference_kBT, double k_total_curvature_kBT) {
  return unit_bending_modulus_J *
         (k_bend_kBT + (k_area_difference_kBT * unit_stiffness.area_difference_pN_um +
                        k_total_curvature_kBT * unit_stiffness.total_curvature_pN_um) /
                           unit_stiffness.bend_pN_um);
}

}  // namespace rbcsim::cases
