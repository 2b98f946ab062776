// Echinocyte III, "a sphere with spaced sharp spicules on a regular basis, about 30-50" (Lim
// 2003; the paper's Fig. 1h). No closed formula is published; our parametric construction is a
// star-shaped surface: the point of the unit sphere u maps to
//     (R_body + sum_i h(s_i)) u,      s_i = R_body |u - c_i|  (distance to spicule axis c_i),
// with the spicule axes c_i spread quasi-uniformly (a Fibonacci spiral, then relaxed by pairwise
// repulsion). Each spicule is a cone of flank angle `spicule_flank_angle_deg` with a rounded
// (hyperboloid) tip of radius `spicule_tip_radius_um`, blended smoothly into the body:
//     h(s) = w softplus((H - k (sqrt(s^2 + a^2) - a)) / w),   k = tan(flank), w = base blend,
// where a is chosen so that the tip's radius of curvature on the final surface (the radial map
// widens it by R_tip / R_body) equals the requested one. The body radius is solved so that the
// mesh has the requested membrane area (the discocyte's), after which the mesh is scaled
// uniformly by the small residual to match it exactly.
#pragma once

#include <vector>

#include "mesh/surface_map.hpp"

namespace rbcsim::mesh {

struct EchinocyteShape {
  double membrane_area_um2 = 134.09;  // Evans-Fung discocyte area (discocyte_area_um2())
  int spicule_count = 36;             // the paper: "about 30-50"
  double spicule_height_um = 0.8;     // tip above the body surface
  double spicule_tip_radius_um = 0.25;
  double spicule_flank_angle_deg = 60.0;  // cone flank against the body surface
  double spicule_base_blend_um = 0.05;    // softplus width w of the flank-to-body fillet
  RelaxationSettings relaxation;
};

// Quasi-uniform unit vectors: Fibonacci spiral, then a few hundred steps of 1/r^2 repulsion.
std::vector<Vec3> spicule_axes(int count);

SurfaceMap echinocyte_map(const EchinocyteShape& shape, double body_radius_um);
TriangleMesh echinocyte_mesh(const EchinocyteShape& shape, int subdivisions);

}  // namespace rbcsim::mesh
