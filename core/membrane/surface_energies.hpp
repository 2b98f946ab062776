// Continuum energies of the membrane on its triangulation, each with its exact gradient: the
// bilayer's Helfrich bending (zero spontaneous curvature) and area-difference elasticity (ADE),
// and the membrane skeleton's nonlinear stretch and shear elasticity of Lim, Wortis & Mukhopadhyay
// (PNAS 99:16766, 2002). Together with a held area and volume they make the bilayer-couple model
// whose minima are the stomatocyte-discocyte-echinocyte sequence (docs/physics.md, "Shapes from
// membrane mechanics"). The shape minimiser (core/shapes) uses them; so can any dynamics.
//
// Each term is a small functor with one parameter struct documenting its units: positions in um,
// energies in pN um (1e-18 J), moduli in pN um (bending) or pN/um (= uN/m, the skeleton), gradients
// in pN. `add` returns the term's energy and ADDS dE/dx to `gradient_pN` (one entry per vertex),
// in a fixed element order, so results do not depend on the thread count.
#pragma once

#include <array>
#include <numbers>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/cell_geometry.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

// What the terms share, measured once per evaluation: the CellGeometry (edge lengths, dihedral
// angles, triangle area vectors, volume, curvature sums), the total area and, per vertex, the
// Juelicher (1996) integrated mean curvature M_i = (1/4) sum over i's edges of l_e theta_e and the
// vertex area A_i = (1/3) sum over i's triangles of A_t.
struct SurfaceMeasures {
  std::span<const Vec3> positions_um;
  std::span<const mesh::Triangle> triangles;
  const mesh::MeshTopology* topology = nullptr;
  CellGeometry geometry;
  std::vector<double> triangle_areas_um2;
  double area_um2 = 0.0;
  std::vector<double> vertex_curvatures_um;  // M_i
  std::vector<double> vertex_areas_um2;      // A_i

  // Sized for `topology`; measure() fills it for the given positions.
  SurfaceMeasures(std::span<const mesh::Triangle> triangles, const mesh::MeshTopology& topology);
  void measure(std::span<const Vec3> positions_um);
  // Only what the area and volume constraints need: the triangle area vectors and areas, the
  // total area and geometry.volume_um3 (the edge and vertex measures are left as they were).
  void measure_area_and_volume(std::span<const Vec3> positions_um);
};

// Juelicher's per-vertex measures, shared by SurfaceMeasures and the dynamic `helfrich` term:
// the integrated mean curvature M_v = (1/4) sum over v's edges of l_e theta_e (um) and the vertex
// area A_v = (1/3) sum of v's triangle areas (um^2), from per-triangle areas or area vectors.
double integrated_mean_curvature_um(const mesh::MeshTopology& topology,
                                    std::span<const double> edge_lengths_um,
                                    std::span<const double> dihedral_angles_rad,
                                    std::size_t vertex);
double vertex_area_um2(const mesh::MeshTopology& topology,
                       std::span<const double> triangle_areas_um2, std::size_t vertex);
double vertex_area_um2(const mesh::MeshTopology& topology,
                       std::span<const Vec3> triangle_area_vectors_um2, std::size_t vertex);

// Helfrich bending with zero spontaneous curvature, E = (kappa/2) int (2H)^2 dA, discretised as
// Juelicher (J. Phys. II France 6:1797, 1996): E = 2 kappa sum_i M_i^2 / A_i. A sphere has
// E = 8 pi kappa at any size and resolution (exactly in the continuum; tested on icospheres).
struct HelfrichBendingParameters {
  // kappa, pN um. Default 2e-19 J (Lim et al. 2002; Evans 1983 measured 1.8e-19 J).
  double bending_modulus_pN_um = 0.2;
};
struct HelfrichBending {
  HelfrichBendingParameters parameters;
  double add(const SurfaceMeasures& measures, std::span<Vec3> gradient_pN) const;
};

// Area-difference elasticity, E = (alpha kappa pi / (2 A D^2)) (DeltaA - DeltaA0)^2 (Lim et al.
// 2002, Eq. 2), with the leaflets' area difference DeltaA = 2 D int H dA = D sum_e l_e theta_e
// (D the leaflet separation). With M = int H dA = (1/2) sum_e l_e theta_e, D cancels:
// E = (2 pi alpha kappa / A) (M - M0)^2. The reduced relaxed area difference of the literature is
// Delta a0 = DeltaA0 / (8 pi D R_A) = M0 / (4 pi R_A), R_A = sqrt(A / 4 pi): 1 for a sphere.
struct AreaDifferenceParameters {
  double bending_modulus_pN_um = 0.2;              // kappa, pN um
  double nonlocal_ratio = 2.0 / std::numbers::pi;  // alpha = kappa_bar / kappa (Lim: 2/pi)
  double relaxed_curvature_sum_um = 0.0;           // M0 = DeltaA0 / (2 D), um
};
struct AreaDifferenceElasticity {
  AreaDifferenceParameters parameters;
  double add(const SurfaceMeasures& measures, std::span<Vec3> gradient_pN) const;
};

// Delta a = M / (4 pi R_A) of a surface of total curvature sum M and area A, and its inverse.
double reduced_area_difference(double curvature_sum_um, double area_um2);
double curvature_sum_for(double reduced_area_difference, double area_um2);

// The membrane skeleton (spectrin network) as a nonlinear 2D solid measured against its own
// stress-free reference triangulation (Lim et al. 2002, Eq. 3): per reference area,
//   w = (K_alpha / 2)(alpha^2 + a3 alpha^3 + a4 alpha^4) + mu (beta + b1 alpha beta + b2 beta^2)
// with alpha = lambda1 lambda2 - 1 (local dilation) and beta = (lambda1 - lambda2)^2 /
// (2 lambda1 lambda2) (shear), lambda1,2 the principal stretches of the triangle's deformation
// from its reference. Per triangle, alpha = A / A0 - 1 and beta = tr(C) / (2 A / A0) - 1, with the
// right Cauchy-Green tensor's trace tr(C) = tr(g G^-1) from the current and reference metrics of
// the triangle's two edges from corner 0: no reference positions are needed, only its metric.
struct SkeletonParameters {
  double shear_modulus_pN_per_um = 2.5;  // mu: 2.5 uN/m (Lim et al. 2002)
  double area_modulus_pN_per_um = 5.0;   // K_alpha: 2 mu (Lim et al. 2002)
  // Lim et al. 2002's nonlinear coefficients of the dilation (a3, a4) and shear (b1, b2) terms.
  double a3 = -2.0;
  double a4 = 8.0;
  double b1 = 0.7;
  double b2 = 0.75;
};
struct SkeletonReference {
  // Per triangle: G11 = |E1|^2, G12 = E1.E2, G22 = |E2|^2 for the reference edges E1 = X1 - X0,
  // E2 = X2 - X0 (um^2), and the reference area A0 = sqrt(G11 G22 - G12^2) / 2.
  std::vector<std::array<double, 3>> metrics_um2;
  std::vector<double> areas_um2;
};
// Throws std::invalid_argument for a degenerate reference triangle.
SkeletonReference capture_skeleton_reference(std::span<const Vec3> positions_um,
                                             std::span<const mesh::Triangle> triangles);
struct SkeletonElasticity {
  SkeletonParameters parameters;
  const SkeletonReference* reference = nullptr;
  double add(const SurfaceMeasures& measures, std::span<Vec3> gradient_pN) const;
};

// The held quantities of the bilayer-couple model and their gradients (overwritten, not added):
// the total area A (um^2, gradient um) and the enclosed volume V (um^3, gradient um^2).
void area_gradient(const SurfaceMeasures& measures, std::span<Vec3> gradient_um);
void volume_gradient(const SurfaceMeasures& measures, std::span<Vec3> gradient_um2);

}  // namespace rbcsim::membrane
