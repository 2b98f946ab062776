// The frame and the observables of the stretch experiment (DESIGN.md §4 "stretch").
//
// Frame: the pull axis is x, through the solid centroid at the origin. A cell whose x axis is
// already a longest principal axis (the built-in shapes: a discocyte's two in-plane axes tie, and
// x is one of them) is only centred; any other mesh is rotated onto its principal axes first.
//
// Observables, as measured on the microscope images of Mills et al. (2004):
//   axial diameter      = the extent along the pull axis, max x - min x;
//   transverse diameter = the largest extent perpendicular to it: the largest distance between
//                         two vertices projected onto the y-z plane. This equals the largest
//                         width of the projection over all directions of that plane (the
//                         diameter of a point set is its maximal width), so the two readings of
//                         "largest extent" coincide. At rest it is the discocyte's diameter; the
//                         thickness (~2.6 um) never wins against the shrinking in-plane width
//                         while the cell stays wider than it is thick.
#pragma once

#include <span>

#include "common/vec3.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

// The mesh in the stretch frame (a rigid motion: the stress-free shape is unchanged).
mesh::TriangleMesh in_stretch_frame(mesh::TriangleMesh mesh);

double axial_diameter_um(std::span<const Vec3> positions_um);
double transverse_diameter_um(std::span<const Vec3> positions_um);

}  // namespace rbcsim::cases
