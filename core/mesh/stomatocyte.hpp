// Stomatocyte II, "a cup shape with a deep invagination" (Lim 2003; the paper's Fig. 1c). No
// closed formula is published, so we build it the way Evans & Fung build the discocyte (see
// thick_shell.hpp): the discocyte is a thickened flat disc; the stomatocyte is a thickened
// spherical cap, i.e. a discocyte bent into a cup.
//   midline:   a circular arc of radius Rm from the axis (the bottom of the cup) to the rim,
//              spanning `cup_half_angle_deg` seen from its centre (90 = a hemispherical bowl,
//              larger = the rim curls inwards and the mouth narrows: a deep invagination);
//   thickness: half-thickness t0 sqrt(1 - s^2)(1 + rim_thickening s^2) along the normal, s the
//              arc fraction, so the wall is thickest near the rim and closes there in a rounded
//              lip.
// t0/Rm is solved (bisection on the continuum shape) so that the reduced volume equals
// `reduced_volume`; the finished mesh is then scaled uniformly so that its area equals
// `membrane_area_um2` (the discocyte's: the shape change conserves the membrane area).
#pragma once

#include "mesh/surface_map.hpp"

namespace rbcsim::mesh {

struct StomatocyteShape {
  double membrane_area_um2 = 134.09;  // Evans-Fung discocyte area (discocyte_area_um2())
  // Reduced volume 6 sqrt(pi) V / A^1.5 of the continuum shape. Stomatocytes observed and
  // computed in the literature lie around 0.5-0.65 (Lim et al. 2002 keep the discocyte's 0.642
  // through the whole stomatocyte-discocyte-echinocyte sequence); 0.60 gives a cup whose cavity
  // is about as deep as the cell is thick. With the other defaults any value up to 0.746 is
  // reachable (a thinner wall gives less; at 0.3 the cup is a thin bowl).
  double reduced_volume = 0.60;
  double cup_half_angle_deg = 120.0;  // opening of the midline arc (90 = hemisphere)
  double rim_thickening = 0.6;        // wall half-thickness at the rim / at the bottom - 1
  RelaxationSettings relaxation;
};

// The continuum shape at midline radius `midline_radius_um`, wall parameter t0/Rm solved.
SurfaceMap stomatocyte_map(const StomatocyteShape& shape, double midline_radius_um = 1.0);
TriangleMesh stomatocyte_mesh(const StomatocyteShape& shape, int subdivisions);

}  // namespace rbcsim::mesh
