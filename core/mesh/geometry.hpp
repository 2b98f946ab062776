// Geometric measures of a triangle mesh (positions in um, so areas in um^2, volumes in um^3).
// Pure functions on positions + connectivity; the membrane forces and `mesh info` share them.
#pragma once

#include <span>

#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

// Half the cross product of two edges: direction = outward normal, length = area.
Vec3 triangle_area_vector(std::span<const Vec3> positions_um, const Triangle& triangle);
double triangle_area_um2(std::span<const Vec3> positions_um, const Triangle& triangle);

double surface_area_um2(const TriangleMesh& mesh);

// How far a membrane's area has moved from a reference (usually the stress-free shape): the
// largest d = |A - A0| / A0 of a triangle, the local-area term's measure (Eq. 8, singular at
// tau_a), and the whole surface's (A - A0) / A0, which a real cell's lipid bilayer keeps within a
// few percent.
struct AreaStrain {
  double total_relative_change = 0.0;
  double max_abs_triangle_deviation = 0.0;
};
// `reference_areas` holds A0 per triangle, in the square of the positions' unit. Throws
// std::invalid_argument when the counts differ or a reference area is not positive.
AreaStrain area_strain(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                       std::span<const double> reference_areas);

// Signed volume by the divergence theorem: positive for outward-oriented closed meshes.
double enclosed_volume_um3(const TriangleMesh& mesh);
// v = 6 sqrt(pi) V / A^(3/2): 1 for a sphere, ~0.64 for a discocyte.
double reduced_volume(double area_um2, double volume_um3);

double edge_length_um(std::span<const Vec3> positions_um, const Edge& edge);

// Signed angle between the outward normals of the edge's two triangles, in (-pi, pi]:
// positive where the surface is convex (a sphere has theta > 0 on every edge), zero where flat.
// This is theta_j of the paper's Eq. 13. The paper calls concave pairs positive; we use the
// opposite (standard) sign so that DeltaA > 0 for convex cells, as for A_outer - A_inner of a
// real bilayer. Only the relative deviations (DeltaA - DeltaA0)/|DeltaA0| enter the forces, so the
// choice does not change any force.
double signed_dihedral_angle_rad(std::span<const Vec3> positions_um, const Edge& edge);

// The pieces that angle is made of, before its atan2 and square root: with the unnormalised
// outward normals n0, n1 of the two triangles and the edge's axis a (vertex0 -> vertex1),
// sine_times_axis = (n0 x n1) . a and cosine = n0 . n1 (both |n0||n1| times the sine and cosine;
// the sine also |a| times), and axis_squared = |a|^2. For tests on the angle that need no atan2.
struct HingeAngleParts {
  double sine_times_axis = 0.0;
  double cosine = 0.0;
  double axis_squared = 0.0;
};
HingeAngleParts hinge_angle_parts(std::span<const Vec3> positions_um, const Edge& edge);
// signed_dihedral_angle_rad from its parts, to the same bits.
double signed_dihedral_angle_rad(const HingeAngleParts& parts);

// Sum over edges of M_j = l_j theta_j / 2 (Eq. 13), i.e. the integrated mean curvature in um.
// The paper's DeltaA (Eq. 12) is 2 D0 times this and C (Eq. 14) is 2 D0 times the sum of |M_j|;
// D0 (monolayer thickness) cancels in the relative deviations, so we never need its value.
struct CurvatureSums {
  double signed_um = 0.0;    // sum of M_j       -> DeltaA / (2 D0)
  double absolute_um = 0.0;  // sum of |M_j|     -> C / (2 D0)
};
CurvatureSums curvature_sums(std::span<const Vec3> positions_um, const MeshTopology& topology);

}  // namespace rbcsim::mesh
