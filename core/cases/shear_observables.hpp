// The observables of the shear experiment (paper §3.2; docs/physics.md): pure functions of a
// cell's vertex positions in the shear frame (flow along x, velocity gradient along y, vorticity
// along z; the shear plane is x-y).
//
//   length        the largest vertex-vertex distance (the paper's "greatest diameter", what
//                 Bessis & Mohandas read from the diffraction pattern);
//   inclination   the angle from the flow direction (+x) towards +y of the major principal axis
//                 of the vertex cloud's second moments in the shear plane, degrees in (-90, 90];
//   breadth       the extent of the cell along the in-plane direction perpendicular to that axis;
//   deformation   Taylor's index (L - B) / (L + B);
//   tank-treading the rotation of one tracked membrane point about the centroid in the shear
//                 plane, counted positive in the sense of the flow's vorticity (clockwise seen
//                 from +z when u_x grows with y);
//   smoothness    the RMS over the interior edges of the change of the dihedral angle from the
//                 stress-free reference, rad: 0 for a rigid motion, large for a wrinkled or
//                 creased surface, but on a coarse mesh just as large for the cell's overall,
//                 smooth deformation (a disc stretched into an ellipsoid);
//   roughness     the mesh-scale part of that change only (dihedral_roughness_rad below): near 0
//                 for a smooth deformation, raised by a wrinkle, crease, buckle or kink (the
//                 paper's "unnatural deformations" of §3.2, Figs. 9-11, without F_ad and F_tc).
#pragma once

#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::cases {

struct ShearShape {
  double length_um = 0.0;
  double breadth_um = 0.0;
  double deformation_index = 0.0;
  double inclination_deg = 0.0;
};

// Largest distance between two vertices (all pairs: O(n^2), a few ms at 2562 vertices).
double largest_vertex_distance_um(std::span<const Vec3> positions_um);

// Angle of the major axis of the vertices' second moments in the x-y plane, rad in (-pi/2, pi/2].
double in_plane_major_axis_rad(std::span<const Vec3> positions_um);

ShearShape measure_shear_shape(std::span<const Vec3> positions_um);

// RMS of (theta - theta0) over the edges, rad; the spans have one angle per edge.
double dihedral_change_rms_rad(std::span<const double> dihedral_angles_rad,
                               std::span<const double> reference_angles_rad);

// Mesh-scale roughness, rad: a high-pass filter of the dihedral changes delta_e = theta_e -
// theta0_e in two steps.
//  1. Per vertex, the mean of delta_e over the edges of its star. For a smooth surface delta_e
//     is about the edge's hinge length times the change of the normal curvature across the edge,
//     which depends on the edge's direction once the deformation is anisotropic (a stretched
//     sphere): the edges' own neighbours (other directions) would differ by O(delta) and a
//     per-edge Laplacian does not separate scales. Averaged over the n >= 5 nearly equally spaced
//     directions of a star, a quadratic form gives its trace: the vertex mean sees the change of
//     the mean curvature only, direction-free.
//  2. Per vertex, that mean minus the mean of it over the one-ring neighbours (the umbrella
//     Laplacian). For a field f smooth on the scale R of the cell the one-ring (radius h, the
//     edge length) mean is f + (h^2 / 4) lap f + O(h^4): the residual is ~ (h / R)^2 / 4 of the
//     change, while a wrinkle of wavelength lambda ~ a few h keeps a fraction
//     1 - J0(2 pi h / lambda) ~ 1 of its amplitude.
// The RMS of the residual over the vertices is returned. Zero for a rigid motion (theta = theta0);
// for an affine stretch of an icosphere the residual is set by the mesh's irregularity (star
// directions not quite equally spaced), a few % of dihedral_change_rms_rad (bound and derivation
// in tests/cases/shear_observables_test.cpp). Throws std::invalid_argument unless both spans
// have one angle per edge of `topology`.
double dihedral_roughness_rad(std::span<const double> dihedral_angles_rad,
                              std::span<const double> reference_angles_rad,
                              const mesh::MeshTopology& topology);

// The angle of `point` about `centre` in the x-y plane, rad in (-pi, pi].
double in_plane_angle_rad(const Vec3& point, const Vec3& centre);

// The unwrapped angle nearest to `previous_unwrapped_rad` with the principal value `angle_rad`:
// valid while the point turns by less than pi between two samples.
double unwrap_angle_rad(double previous_unwrapped_rad, double angle_rad);

// The shape averaged over a window of samples: what a cell that tank-treads with swinging (its
// length, breadth and inclination oscillating twice per membrane turn) shows on average, as a
// diffraction pattern recorded over many periods does (Bessis & Mohandas).
struct AveragedShape {
  ShearShape mean;               // each observable's mean over the samples
  double length_swing_um = 0.0;  // largest minus smallest length among them
};

// Throws std::invalid_argument for no samples.
AveragedShape average_shapes(std::span<const ShearShape> shapes);

// How many of the last samples lie within the tracked point's last half turn: those after the
// last sample whose unwrapped angle is pi or more from the final one. For a cell with a mirror-
// symmetric rest shape in the shear plane (a disc seen edge-on) a half turn of the membrane is
// one period of the swinging, so means over it carry no phase bias. 0 until the point has turned
// by pi.
std::size_t samples_in_last_half_turn(std::span<const double> unwrapped_angles_rad);

// Rotation frequency from unwrapped angles sampled at times_s: minus the least-squares slope of
// angle against time over 2 pi, Hz (positive for clockwise turning seen from +z). Needs two
// samples at different times at least (std::invalid_argument otherwise).
double rotation_frequency_hz(std::span<const double> times_s,
                             std::span<const double> unwrapped_angles_rad);

}  // namespace rbcsim::cases
