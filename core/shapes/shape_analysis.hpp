// Measures of a cell shape that tell its morphology (Lim 2003's classes of the paper's Fig. 1), for
// `rbcsim mesh generate --json` and the tests: spicules (echinocytes), the invagination
// (stomatocytes) and the distance of an axisymmetric shape from the Evans-Fung discocyte.
// Pure functions of a closed mesh; lengths in um.
#pragma once

#include <cstddef>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/discocyte.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::shapes {

// A spicule tip is a vertex that is (1) the farthest from the solid centroid within
// kSpiculeNeighbourhoodRadius_um, (2) curved like a tip: its Juelicher mean curvature
// M_i / A_i is above kSpiculeTipMeanCurvature_per_um (a tip of radius under ~0.7 um; a
// discocyte's rim or an elliptical body's ends stay below 0.7 per um), and (3) stands out:
// its distance from the centroid exceeds the mean over the vertices between
// kSpiculeBaseInner_um and kSpiculeBaseOuter_um from it by kSpiculeProminence_um.
inline constexpr double kSpiculeNeighbourhoodRadius_um = 0.6;
inline constexpr double kSpiculeTipMeanCurvature_per_um = 1.5;
inline constexpr double kSpiculeBaseInner_um = 0.8;
inline constexpr double kSpiculeBaseOuter_um = 1.2;
inline constexpr double kSpiculeProminence_um = 0.1;

// A mesh spike: a single vertex pulled out of its ring of neighbours, a pyramid that no
// continuous surface resolves. Its height above the mean of its neighbours, along its normal,
// exceeds kSpikeHeightPerEdge of their mean distance (measured: resolved spicule tips rise at
// most 0.45 of an edge above their ring, single-vertex spikes 0.86-0.95). Spikes are counted
// apart, never as spicules.
inline constexpr double kSpikeHeightPerEdge = 0.6;

struct Spicules {
  std::vector<std::size_t> tip_vertices;  // resolved spicules only
  std::vector<std::size_t> spike_vertices;
  // Distance from each tip to its nearest neighbour tip: their mean and coefficient of variation
  // (standard deviation / mean; 0 for a perfectly regular pattern). Zero with fewer than 2 tips.
  double nearest_spacing_mean_um = 0.0;
  double nearest_spacing_cv = 0.0;
  double mean_height_um = 0.0;  // prominence (3) averaged over the tips
};
Spicules find_spicules(const mesh::TriangleMesh& mesh);

// The invagination along the shape's axis: the principal axis whose variance is most unlike the
// other two (the symmetry axis of a disc or a cup). Along it the surface is crossed by the
// vertices within kAxisBand_um of the axis; with the two crossings nearest the centre of the
// axis band, depth = the shape's extent beyond the inner crossing on the open side (a cup's
// mouth, a discocyte's dimple), diameter = twice the largest distance from the axis.
inline constexpr double kAxisBand_um = 0.4;
struct Invagination {
  double depth_um = 0.0;
  double diameter_um = 0.0;
  double depth_to_diameter = 0.0;
  // The crossings' thicknesses along the axis: a discocyte has the two dimples on opposite
  // sides (cup_offset_um ~ 0), a cup has its bottom displaced from the centre.
  double centre_thickness_um = 0.0;
  double cup_offset_um = 0.0;
};
Invagination measure_invagination(const mesh::TriangleMesh& mesh);

// The distance of each vertex, in the (r, |z|) half-plane of the shape's axis frame (centred,
// symmetry axis z), from the Evans-Fung profile of `shape`; the mesh is first scaled to the
// continuous Evans-Fung surface's area. Max and root mean square over the vertices.
struct ProfileDistance {
  double max_um = 0.0;
  double rms_um = 0.0;
};
ProfileDistance distance_from_evans_fung(const mesh::TriangleMesh& mesh,
                                         const mesh::DiscocyteShape& shape = {});

}  // namespace rbcsim::shapes
