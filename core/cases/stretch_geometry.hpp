// The frame and the observables of the stretch experiment (paper §3.1; docs/physics.md, "Stretch").
//
// Frame: the pull axis is x, through the solid centroid at the origin, and z the cell's thinnest
// axis (the microscope's line of sight: the disc lies in the focal plane). A cell whose x axis is
// already a longest and z a shortest principal axis (the built-in shapes: a discocyte's two
// in-plane axes tie, x is one of them, z its symmetry axis) is only centred; any other mesh is
// rotated onto its principal axes first.
//
// Observables, as measured on the microscope images of Mills et al. (2004):
//   axial diameter      = the extent along the pull axis, max x - min x;
//   transverse diameter = the width of the image perpendicular to the pull: the extent along y,
//                         the in-plane perpendicular (the projection along the line of sight z),
//                         as HemoCell's stretchCell reads it off the bounding box. Not the largest
//                         extent in the y-z plane: a cell that thickens, folds or turns about the
//                         pull axis would then report its thickness or a diagonal, which the
//                         image does not show.
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
