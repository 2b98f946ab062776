// Rigid motions and uniform scalings of a whole mesh: used by the generators (to give a shape its
// membrane area) and by mesh import (--scale-to-area, --scale-to-volume, --center, --align).
// None of them changes the triangle orientation (rotations are proper, scale factors positive).
#pragma once

#include <Eigen/Core>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

// Centroid of the enclosed solid (not of the vertices, which depends on the triangulation).
Vec3 solid_centroid_um(const TriangleMesh& mesh);

// Uniform scaling about the solid centroid to the given area / enclosed volume.
void scale_to_area(TriangleMesh& mesh, double target_area_um2);
void scale_to_volume(TriangleMesh& mesh, double target_volume_um3);

void translate_centroid_to_origin(TriangleMesh& mesh);

// Rounds every coordinate to the nearest single-precision value, as a binary STL stores it, so
// that a mesh written and read back is the mesh that was written.
void round_to_single_precision(TriangleMesh& mesh);

// Principal axes of the vertex cloud: columns are unit axes ordered by decreasing variance,
// forming a right-handed frame (determinant +1).
Eigen::Matrix3d principal_axes(const TriangleMesh& mesh);

// Rotates about the solid centroid so that the principal axes become x, y, z: the largest
// extent along x, the smallest along z (a discocyte's symmetry axis ends up on z).
void align_principal_axes(TriangleMesh& mesh);

}  // namespace rbcsim::mesh
