// The bending calibrations (paper §2.3; docs/physics.md, "Calibration").
//
// Two-triangle patch: two equilateral triangles of edge a sharing an edge, flat at rest, folded
// by a small dtheta through the bending term (Eq. 7) and the configured distribution (the
// hinge kernels the cell uses). The restoring moment M about the hinge, per unit hinge length,
// over the curvature dtheta/dx gives the Kirchhoff-Love bending stiffness D = (M / a) dx /
// dtheta, with dx = the distance between the two triangles' centroids across the hinge
// (a / sqrt 3 for the equilateral pair): each triangle's normal is the normal at its centroid, so
// the normal turns by dtheta over dx (the discrete curvature of the pair is dtheta / dx).
//
// Overall bending (area difference and total curvature): these are per-cell terms (DeltaA0, C0
// of the closed cell), so their stiffness is measured on the cell mesh, along the discrete
// uniform curvature perturbation: every dihedral angle of the cell changes by the same
// dtheta. Their energies' second derivatives along that mode, relative to the bending term's,
// scale the two-triangle D up to the cell's overall bending modulus:
//   kappa = D(k_b) (1 + (E''_ad + E''_tc) / E''_b).
#pragma once

#include "membrane/parameters.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

struct TwoTrianglePatchMeasurement {
  double moment_per_angle_pN_um = 0.0;  // restoring moment about the hinge per rad of fold
  double hinge_distance_um = 0.0;       // dx: centroid to centroid across the hinge
  double bending_modulus_J = 0.0;       // D
};

// `parameters` gives k_b, tau_b, kBT, L0 and the distribution. edge_um: a; angle_rad: dtheta.
TwoTrianglePatchMeasurement measure_two_triangle_patch(
    const membrane::MembraneParameters& parameters, double edge_um, double angle_rad);

// D of the same pair in closed form (docs/physics.md, "Calibration"): the moment stiffness is K_b
// (1 + 1/tau_b^2) per rad, with K_b = (sqrt 3 / 2) k_b kBT for `gradient` (the hinge energy's
// coefficient) and the `paper` wing push (k_b kBT / L0) slope(d) times its arm h = (sqrt 3 / 2) a;
// with dx / a = 1 / sqrt 3: D = k_b kBT (1 + 1/tau_b^2) / 2, times a / L0 for `paper`.
double analytic_two_triangle_bending_modulus_J(const membrane::MembraneParameters& parameters,
                                               double edge_um);

// Second derivatives of the three angle terms' energies along the uniform curvature
// perturbation of the cell, pN um per rad^2, for the stiffnesses in `parameters` (the energies
// are proportional to k: exactly linear). Zero for a cell-level term not in parameters.forces.
struct UniformCurvatureStiffness {
  double bend_pN_um = 0.0;
  double area_difference_pN_um = 0.0;
  double total_curvature_pN_um = 0.0;
};
UniformCurvatureStiffness measure_uniform_curvature_stiffness(
    const mesh::TriangleMesh& cell, const membrane::MembraneParameters& parameters,
    double angle_rad);

// kappa = D (1 + (E''_ad + E''_tc) / E''_b), J, from the measurements at k = 1 kBT (both linear
// in their k): kappa = D_1 (k_b + (k_ad E''_ad,1 + k_c E''_tc,1) / E''_b,1).
double overall_bending_modulus_J(double unit_bending_modulus_J,
                                 const UniformCurvatureStiffness& unit_stiffness, double k_bend_kBT,
                                 double k_area_difference_kBT, double k_total_curvature_kBT);

}  // namespace rbcsim::cases
