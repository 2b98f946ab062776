// The hexagonal patch through the membrane model itself (MembraneModel, the kernels the cell
// uses). The model works on closed meshes, so the patch is closed by a lid: an apex node below the
// centre joined to the six rim nodes. For every imposed shape the lid's links and triangles get
// that shape as their reference, so their deviations are zero and they carry no force: the forces
// on the seven patch nodes are exactly those of the open patch.
#include "cases/hexagonal_patch.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "membrane/membrane_model.hpp"
#include "membrane/reference_state.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::cases {
namespace {

using Matrix2 = Eigen::Matrix2d;

constexpr int kRimNodes = 6;
constexpr std::int32_t kCentre = 0;
constexpr std::int32_t kApex = kRimNodes + 1;
constexpr int kPatchTriangles = kRimNodes;

// Centre 0, rim 1..6 counter-clockwise (outward normal +z), apex 7 at depth a below the centre.
mesh::TriangleMesh closed_hexagon(double edge_um) {
  mesh::TriangleMesh hexagon;
  hexagon.positions_um.push_back(Vec3::Zero());
  for (int i = 0; i < kRimNodes; ++i) {
    const double angle = std::numbers::pi / 3.0 * i;
    hexagon.positions_um.push_back(edge_um * Vec3(std::cos(angle), std::sin(angle), 0.0));
  }
  hexagon.positions_um.push_back(Vec3(0.0, 0.0, -edge_um));
  for (std::int32_t i = 0; i < kRimNodes; ++i) {
    hexagon.triangles.push_back({kCentre, 1 + i, 1 + (i + 1) % kRimNodes});
  }
  for (std::int32_t i = 0; i < kRimNodes; ++i) {
    hexagon.triangles.push_back({kApex, 1 + (i + 1) % kRimNodes, 1 + i});
  }
  return hexagon;
}

bool is_spoke(const mesh::Edge& edge) { return edge.vertex0 == kCentre || edge.vertex1 == kCentre; }
bool is_lid(const mesh::Edge& edge) { return edge.vertex0 == kApex || edge.vertex1 == kApex; }

// Per-term virial stresses of one imposed shape, uN/m.
struct TermStress {
  Matrix2 link = Matrix2::Zero();
  Matrix2 area = Matrix2::Zero();
  double largest_centre_force_pN = 0.0;
};

class ClosedHexagon {
 public:
  ClosedHexagon(const membrane::MembraneParameters& parameters, double edge_um)
      : parameters_(parameters),
        mesh_(closed_hexagon(edge_um)),
        topology_(mesh::MeshTopology::build(mesh_)),
        stress_free_(
            membrane::capture_reference_state(mesh_.positions_um, mesh_.triangles, topology_)),
        area_um2_(3.0 * std::sqrt(3.0) / 2.0 * edge_um * edge_um) {
    parameters_.forces = {"link", "area"};
    parameters_.vertex_force_cap_pN = INFINITY;
  }

  // The stress with the patch's nodes at (I + map) x; rim links count only if `with_rim_links`.
  TermStress stress(const Matrix2& map, bool with_rim_links) const {
    auto positions = mesh_.positions_um;
    for (int v = 0; v <= kRimNodes; ++v) {
      positions[v].head<2>() = (Matrix2::Identity() + map) * positions[v].head<2>();
    }
    const membrane::MembraneModel model(mesh_, reference_for(positions, with_rim_links),
                                        parameters_);
    auto workspace = model.make_workspace();
    auto forces = model.make_forces();
    model.compute(positions, workspace, forces);
    TermStress stress;
    stress.link = virial(positions, forces.term("link").forces_pN);
    stress.area = virial(positions, forces.term("area").forces_pN);
    stress.largest_centre_force_pN = forces.total_pN[kCentre].norm();
    return stress;
  }

 private:
  // The stress-free hexagon for the patch's elements, the current shape for the lid's (and for
  // the rim links when they are left out).
  membrane::ReferenceState reference_for(const std::vector<Vec3>& positions,
                                         bool with_rim_links) const {
    const auto current = membrane::capture_reference_state(positions, mesh_.triangles, topology_);
    auto reference = stress_free_;
    for (std::size_t e = 0; e < topology_.edge_count(); ++e) {
      const auto& edge = topology_.edges()[e];
      if (is_lid(edge) || (!with_rim_links && !is_spoke(edge))) {
        reference.edge_lengths_um[e] = current.edge_lengths_um[e];
      }
    }
    for (std::size_t t = kPatchTriangles; t < mesh_.triangle_count(); ++t) {
      reference.triangle_areas_um2[t] = current.triangle_areas_um2[t];
      reference.triangle_perimeters_um[t] = current.triangle_perimeters_um[t];
    }
    return reference;
  }

  // sigma = -(1/A0) sum over the patch nodes of x (x) F: the loads -F hold the nodes in place.
  Matrix2 virial(const std::vector<Vec3>& positions, const std::vector<Vec3>& forces_pN) const {
    Matrix2 sum = Matrix2::Zero();
    for (int v = 0; v <= kRimNodes; ++v) {
      sum += positions[v].head<2>() * forces_pN[v].head<2>().transpose();
    }
    return -sum / area_um2_;
  }

  membrane::MembraneParameters parameters_;
  mesh::TriangleMesh mesh_;
  mesh::MeshTopology topology_;
  membrane::ReferenceState stress_free_;
  double area_um2_;
};

// d sigma / d eps along the map eps G, by central differences, per term, with the rim links
// split out: the network counts them one half, the isolated patch whole.
struct StressRate {
  Matrix2 spokes;
  Matrix2 rim;
  Matrix2 area;
  double largest_centre_force_pN;

  Matrix2 network() const { return spokes + 0.5 * rim + area; }
  Matrix2 isolated() const { return spokes + rim + area; }
};

StressRate stress_rate(const ClosedHexagon& patch, const Matrix2& direction, double strain) {
  const auto all_plus = patch.stress(strain * direction, true);
  const auto all_minus = patch.stress(-strain * direction, true);
  const auto spokes_plus = patch.stress(strain * direction, false);
  const auto spokes_minus = patch.stress(-strain * direction, false);
  const double span = 2.0 * strain;
  StressRate rate;
  rate.spokes = (spokes_plus.link - spokes_minus.link) / span;
  rate.rim = (all_plus.link - all_minus.link) / span - rate.spokes;
  rate.area = (all_plus.area - all_minus.area) / span;
  rate.largest_centre_force_pN =
      std::max(all_plus.largest_centre_force_pN, all_minus.largest_centre_force_pN);
  return rate;
}

// The four tests of Fig. 7 as stress rates of one reading of the patch.
struct PatchTests {
  Matrix2 stretch_x;  // G = diag(1, 0)
  Matrix2 stretch_y;  // G = diag(0, 1)
  Matrix2 shear;      // G = diag(1, -1): pure shear, area preserved to first order
  Matrix2 expansion;  // G = I: isotropic, area strain 2 eps
};

MembraneModuli moduli_of(const PatchTests& tests) {
  MembraneModuli moduli;
  // Uniaxial stretch, lateral contraction free: eps_yy = -nu eps_xx makes sigma_yy = 0.
  moduli.poisson_ratio = tests.stretch_x(1, 1) / tests.stretch_y(1, 1);
  moduli.young_uN_per_m = tests.stretch_x(0, 0) - moduli.poisson_ratio * tests.stretch_y(0, 0);
  // (sigma_xx - sigma_yy)/2 = 2 mu eps; tension (sigma_xx + sigma_yy)/2 = K * (2 eps).
  moduli.shear_uN_per_m = (tests.shear(0, 0) - tests.shear(1, 1)) / 4.0;
  moduli.area_uN_per_m = tests.expansion.trace() / 4.0;
  return moduli;
}

}  // namespace

MembraneModuli isotropic_moduli(double area_uN_per_m, double shear_uN_per_m) {
  const double sum = area_uN_per_m + shear_uN_per_m;
  return {4.0 * area_uN_per_m * shear_uN_per_m / sum, shear_uN_per_m, area_uN_per_m,
          (area_uN_per_m - shear_uN_per_m) / sum};
}

HexagonalPatchMeasurement measure_hexagonal_patch(const membrane::MembraneParameters& parameters,
                                                  double edge_um, double strain) {
  const ClosedHexagon patch(parameters, edge_um);
  const std::array<Matrix2, 4> directions = {Matrix2{{1, 0}, {0, 0}}, Matrix2{{0, 0}, {0, 1}},
                                             Matrix2{{1, 0}, {0, -1}}, Matrix2::Identity()};
  std::array<StressRate, 4> rates;
  HexagonalPatchMeasurement measurement;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    rates[i] = stress_rate(patch, directions[i], strain);
    measurement.largest_centre_force_pN =
        std::max(measurement.largest_centre_force_pN, rates[i].largest_centre_force_pN);
  }
  measurement.network =
      moduli_of({rates[0].network(), rates[1].network(), rates[2].network(), rates[3].network()});
  measurement.isolated = moduli_of(
      {rates[0].isolated(), rates[1].isolated(), rates[2].isolated(), rates[3].isolated()});
  return measurement;
}

PatchStiffness measure_patch_stiffness(const membrane::MembraneParameters& parameters,
                                       double edge_um, double strain) {
  auto unit = parameters;
  unit.k_link_kBT = 1.0;
  unit.k_area_kBT = 0.0;
  const auto link = measure_hexagonal_patch(unit, edge_um, strain).network;
  unit.k_link_kBT = 0.0;
  unit.k_area_kBT = 1.0;
  const auto area = measure_hexagonal_patch(unit, edge_um, strain).network;
  return {link.shear_uN_per_m, link.area_uN_per_m, area.shear_uN_per_m, area.area_uN_per_m};
}

PatchStiffness analytic_patch_stiffness(const membrane::MembraneParameters& parameters,
                                        double edge_um) {
  const double kBT = parameters.thermal_energy_pN_um;
  const double tau_l = parameters.tau_link;
  const double tau_a = parameters.tau_area;
  const double spring_pN_per_um =
      kBT / parameters.persistence_length_um * (1.0 + 1.0 / (tau_l * tau_l)) / edge_um;
  const double link_shear = std::sqrt(3.0) / 4.0 * spring_pN_per_um;
  const double area_term =
      2.0 * kBT * (1.0 + 1.0 / (tau_a * tau_a)) / (parameters.force_length_scale_um * edge_um);
  return {link_shear, 2.0 * link_shear, 0.0, area_term};
}

MembraneModuli network_moduli(const PatchStiffness& stiffness, double k_link_kBT,
                              double k_area_kBT) {
  return isotropic_moduli(
      k_link_kBT * stiffness.link_area_uN_per_m + k_area_kBT * stiffness.area_term_area_uN_per_m,
      k_link_kBT * stiffness.link_shear_uN_per_m + k_area_kBT * stiffness.area_term_shear_uN_per_m);
}

}  // namespace rbcsim::cases
