// The healthy biconcave discocyte of Evans & Fung (1972):
//     z = +-(R0/2) sqrt(1 - rho^2) (C0 + C2 rho^2 + C4 rho^4),   rho = r / R0,
// meshed from the unit icosphere (rho = the sphere point's distance from the z axis), then relaxed
// along the exact surface so the strongly curved rim is not crowded with thin triangles.
// Continuum values (reference/evansfung_profile.csv): area 134.09 um^2, volume 94.09 um^3,
// reduced volume 0.644, diameter 2 R0 = 7.82 um, thickness 0.81 um at the centre, 2.57 um at most.
#pragma once

#include "mesh/surface_map.hpp"

namespace rbcsim::mesh {

struct DiscocyteShape {
  double radius_um = 3.91;  // R0; diameter 7.82 um
  double c0 = 0.207161;     // Evans & Fung's shape coefficients (dimensionless)
  double c2 = 2.002558;
  double c4 = -1.122762;
  RelaxationSettings relaxation;
};

SurfaceMap discocyte_map(const DiscocyteShape& shape);
TriangleMesh discocyte_mesh(const DiscocyteShape& shape, int subdivisions);

// Area of the continuous Evans-Fung surface (134.09 um^2 for the defaults): the membrane area the
// other generated morphologies are given, since the shape change conserves the membrane area.
double discocyte_area_um2(const DiscocyteShape& shape = {});

}  // namespace rbcsim::mesh
