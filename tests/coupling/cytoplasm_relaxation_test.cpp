// The cytoplasm viscosity contrast against an analytic answer (docs/validation.md, "Cytoplasm
// viscosity"): a spherical capsule, deformed slightly into the second spherical harmonic and let go
// in fluid at rest, relaxes back in two modes, and the slow one is slower by the factor
//   tau_slow(lambda = 5) / tau_slow(lambda = 1) = 2.75
// for lambda = 5 times more viscous fluid inside (linear theory of a 2D Hookean capsule with
// interior and exterior Stokes flow: M dx/dt + K x = 0 for x = (eps, beta), r = a (1 + eps P2),
// u_theta = a beta P2'; the ratio is 2.74-2.78 for K/G from 2 to 3, and 2.75 for a drop too).
// Without the contrast the two runs would be the same run: the ratio would be 1.
// In a periodic box the images of the deformation's flow slow the relaxation, the lambda = 1 mode
// more; hence boxes of 8 a (in 5.3 a the ratio came out 4 % lower).
//
// The capsule is the link + area + volume membrane on an icosphere whose reference is the sphere
// (no bending: 24 kappa/(G a^2) would be a few percent at most). Its moduli come from the patch
// calibration's closed form (cases/hexagonal_patch.hpp) at the mesh's mean edge, set for a shear
// modulus G in lattice units chosen so that the run is nearly Stokes flow:
// a G rate / (rho nu^2) = 0.05, inertia a small correction, the same for both runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>
#include <vector>

#include "cases/hexagonal_patch.hpp"
#include "coupling/coupling_fixtures.hpp"
#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::coupling {
namespace {

using testing::sphere_mesh;

// The slow and fast decay rates of (eps, beta) in units of G / (eta_outside a) (the 2x2 linear
// theory above, with eta = eta_outside (1, lambda) outside and inside, K the area modulus).
struct CapsuleRates {
  double slow = 0.0;
  double fast = 0.0;
};

CapsuleRates linear_theory_rates(double lambda, double area_over_shear) {
  const double k = area_over_shear;  // G = 1, a = 1, eta_outside = 1
  const double m[2][2] = {{-(13.0 * lambda + 12.0) / 2.0, 3.0 * (3.0 * lambda + 2.0)},
                          {(3.0 * lambda + 2.0) / 2.0, -5.0 * (lambda + 1.0)}};
  const double elastic[2][2] = {{-4.0 * k, 12.0 * k}, {2.0 * k, -4.0 - 6.0 * k}};
  // dx/dt = A x with A = -M^-1 K; the rates are -eig(A).
  const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  const double inverse[2][2] = {{m[1][1] / det, -m[0][1] / det}, {-m[1][0] / det, m[0][0] / det}};
  double a[2][2];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      a[i][j] = -(inverse[i][0] * elastic[0][j] + inverse[i][1] * elastic[1][j]);
    }
  }
  const double half_trace = 0.5 * (a[0][0] + a[1][1]);
  const double determinant = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  const double root = std::sqrt(half_trace * half_trace - determinant);
  return {-(half_trace + root), -(half_trace - root)};
}

struct RelaxationCase {
  int box_nodes = 32;               // periodic cube
  double radius_lu = 6.0;           // a
  int level = 3;                    // icosphere subdivisions (642 vertices)
  double tau = 1.5;                 // outside; nu = (tau - 1/2)/3
  double shear_modulus_lu = 0.004;  // G
  double area_over_shear = 2.78;    // K / G, the paper's patch (28.2 / 10.15 uN/m)
  double strain = 0.05;             // eps0: x -> x + eps0 diag(-1/2, -1/2, 1) x about the centre
  double viscosity_ratio = 1.0;     // lambda
  double fit_from = 0.4;            // fit the decay from this fraction of the initial deformation
  double decay_to = 0.04;           // to this one, then stop
};

struct Relaxation {
  double slow_rate_lu = 0.0;  // per step
  std::size_t steps = 0;
  double theory_slow_rate_lu = 0.0;
};

// z^2 - (x^2 + y^2)/2 averaged over the vertices about their centroid: linear in eps for the
// axisymmetric second harmonic, zero for the icosphere (its second moments are isotropic).
double deformation(std::span<const Vec3> positions) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : positions) centroid += p;
  centroid /= static_cast<double>(positions.size());
  double sum = 0.0;
  for (const Vec3& p : positions) {
    const Vec3 r = p - centroid;
    sum += r.z() * r.z() - 0.5 * (r.x() * r.x() + r.y() * r.y());
  }
  return sum / static_cast<double>(positions.size());
}

double mean_edge_um(const mesh::TriangleMesh& mesh) {
  const auto topology = mesh::MeshTopology::build(mesh);
  double sum = 0.0;
  for (const auto& edge : topology.edges()) sum += mesh::edge_length_um(mesh.positions_um, edge);
  return sum / static_cast<double>(topology.edges().size());
}

Relaxation relax(const RelaxationCase& c) {
  const double dx_um = 0.5;
  const units::UnitConverter units({dx_um, c.tau, 1025.0, 1.1e-6});
  lattice::FluidParameters fluid_parameters;
  fluid_parameters.collision_parameters.tau = c.tau;
  fluid_parameters.inner_viscosity_ratio = c.viscosity_ratio;
  auto fluid = std::make_unique<lattice::FluidSolver>(
      lattice::LatticeGrid(c.box_nodes, c.box_nodes, c.box_nodes), fluid_parameters);
  CoupledSimulation simulation(std::move(fluid), units, CouplingParameters{});

  // Off the nodes and off the cube's symmetry: nothing lines up by chance.
  const Vec3 centre_um =
      dx_um * Vec3(0.5 * c.box_nodes + 0.23, 0.5 * c.box_nodes - 0.41, 0.5 * c.box_nodes + 0.17);
  const auto sphere = sphere_mesh(c.level, c.radius_lu * dx_um, centre_um);
  // G in uN/m: a lattice force per lattice length.
  const double lattice_force_per_N = units.to_lattice(units::PhysicalUnit::force_N, 1.0);
  const double shear_uN_per_m = c.shear_modulus_lu / (units.dx_m() * lattice_force_per_N) * 1e6;
  membrane::MembraneParameters membrane = testing::capsule_parameters(1.0);
  membrane.vertex_force_cap_pN = 1e9;  // far above every force here
  const auto unit = cases::analytic_patch_stiffness(membrane, mean_edge_um(sphere));
  membrane.k_link_kBT = shear_uN_per_m / unit.link_shear_uN_per_m;
  membrane.k_area_kBT =
      (c.area_over_shear * shear_uN_per_m - membrane.k_link_kBT * unit.link_area_uN_per_m) /
      unit.area_term_area_uN_per_m;
  EXPECT_GT(membrane.k_area_kBT, 0.0);
  membrane.k_volume_kBT = membrane.k_link_kBT;

  std::vector<Vec3> deformed;
  for (const Vec3& p : sphere.positions_um) {
    const Vec3 r = p - centre_um;
    deformed.push_back(p + c.strain * Vec3(-0.5 * r.x(), -0.5 * r.y(), r.z()));
  }
  simulation.add_cell(membrane::MembraneModel(sphere, membrane), deformed);

  // Sample every ~1/100 of the slow time; fit ln(deformation) on its tail, after the fast mode
  // has died away (below 40 % of the start) and before round-off and the box's own slow modes
  // matter (down to decay_to).
  Relaxation result;
  const double eta = (c.tau - 0.5) / 3.0;
  result.theory_slow_rate_lu = linear_theory_rates(c.viscosity_ratio, c.area_over_shear).slow *
                               c.shear_modulus_lu / (eta * c.radius_lu);
  const auto interval = static_cast<std::size_t>(std::max(1.0, 0.01 / result.theory_slow_rate_lu));
  const double initial = deformation(simulation.cell(0).positions_lu());
  std::vector<double> times;
  std::vector<double> logs;
  const auto limit = static_cast<std::size_t>(10.0 / result.theory_slow_rate_lu);
  while (result.steps < limit) {
    for (std::size_t s = 0; s < interval; ++s) simulation.step();
    result.steps += interval;
    const double ratio = deformation(simulation.cell(0).positions_lu()) / initial;
    if (ratio < c.fit_from && ratio > c.decay_to) {
      times.push_back(static_cast<double>(result.steps));
      logs.push_back(std::log(ratio));
    }
    if (ratio <= c.decay_to) break;
  }
  // Least-squares slope of ln(deformation) against time.
  const double n = static_cast<double>(times.size());
  const double mean_t = std::accumulate(times.begin(), times.end(), 0.0) / n;
  const double mean_l = std::accumulate(logs.begin(), logs.end(), 0.0) / n;
  double covariance = 0.0;
  double variance = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    covariance += (times[k] - mean_t) * (logs[k] - mean_l);
    variance += (times[k] - mean_t) * (times[k] - mean_t);
  }
  EXPECT_GE(times.size(), 10u) << "too few samples on the tail";
  result.slow_rate_lu = -covariance / variance;
  return result;
}

void check_contrast(const RelaxationCase& base, double tolerance) {
  RelaxationCase plain = base;
  plain.viscosity_ratio = 1.0;
  RelaxationCase contrast = base;
  contrast.viscosity_ratio = 5.0;
  const Relaxation one = relax(plain);
  const Relaxation five = relax(contrast);
  const double measured = one.slow_rate_lu / five.slow_rate_lu;
  const double expected = one.theory_slow_rate_lu / five.theory_slow_rate_lu;
  std::printf(
      "a = %.0f dx, box %d, tau %.2f, G %.4f: slow rate lambda 1: %.4e per step (theory %.4e, "
      "%d steps), lambda 5: %.4e (theory %.4e, %d steps); tau5/tau1 = %.3f (theory %.3f)\n",
      base.radius_lu, base.box_nodes, base.tau, base.shear_modulus_lu, one.slow_rate_lu,
      one.theory_slow_rate_lu, static_cast<int>(one.steps), five.slow_rate_lu,
      five.theory_slow_rate_lu, static_cast<int>(five.steps), measured, expected);
  EXPECT_NEAR(measured / expected, 1.0, tolerance);
  EXPECT_GT(measured, 2.0);  // 1 if the contrast did nothing
  // The IBM's and the icosphere network's own errors, which the ratio cancels, stay moderate.
  EXPECT_NEAR(one.slow_rate_lu / one.theory_slow_rate_lu, 1.0, 0.2);
}

// a = 5 dx in a box of 8 a: 11 000 steps, about 15 s on one core. The box's periodic images slow
// the lambda = 1 mode more than the lambda = 5 one (measured at a = 6: the ratio 2.57 in a box of
// 5.3 a, 2.68 in 8 a); at a = 4, 5, 6 in 8 a it is 2.52, 2.60, 2.68 (docs/validation.md).
TEST(CytoplasmRelaxation, SlowModeIsSlowerByTheAnalyticFactor) {
  RelaxationCase c;
  c.radius_lu = 5.0;
  c.box_nodes = 40;
  c.shear_modulus_lu = 0.0048;  // a G rate / nu^2 = 0.05 as at a = 6, G = 0.004
  c.fit_from = 0.5;
  c.decay_to = 0.1;
  check_contrast(c, 0.15);
}

// The same at a = 8 dx in a box of 8 a (262 144 nodes, about 42 000 steps).
TEST(ValidateCytoplasmRelaxation, SlowModeRatioAtEightSpacings) {
  RelaxationCase c;
  c.radius_lu = 8.0;
  c.box_nodes = 64;
  c.shear_modulus_lu = 0.003;
  check_contrast(c, 0.10);
}

}  // namespace
}  // namespace rbcsim::coupling
