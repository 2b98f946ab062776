// Contact between cells as a push between each vertex and the nearest point of another cell's
// surface (docs/physics.md, "Suspensions"): the law that holds facing membranes apart.
//
// Why not vertex pairs alone: where two membranes face each other with their vertices offset
// sideways (by a fraction of an edge), the pair forces point along the vertex separations; as the
// gap closes they turn tangential, their normal part falls to zero at contact and the surfaces
// pass through each other without meeting a barrier (measured in a 10 um tube run: the normal
// force on the first vertex through fell from 3.8 pN to 0 over the last 0.05 um). Here the push
// is along the line from the nearest surface point, which for facing surfaces is their normal.
//
// For a vertex i and another cell B, c is the nearest point of B's surface to x_i (on triangle t,
// barycentric weights w), d = |x_i - c|, and n the unit vector from c to x_i, turned to point out
// of B when x_i lies on B's inner side (by the angle-weighted pseudo-normal at c, which is exact
// for a closed surface also beyond edges and corners): a vertex already through is pushed back out:
//     F_i = F(d) n,   F_k = -w_k F(d) n on t's three vertices k,
//     F(d) = F_half (r / d - 1)^2 for d < r: F_half at d = r / 2, 0 with zero slope at the range r,
//     growing as (r / d)^2 towards contact (a barrier: the lattice's regularised forces on two
//     nearby vertices largely cancel in the fluid, by a part that vanishes with their distance).
// F is held at ContactParameters::force_cap_pN where the law exceeds it (counted), and d is
// floored at r / 100 (F at most 9801 F_half without a cap): the stability checks see anything
// closer.
// Momentum: the reactions sum to -F_i (the weights sum to 1), so the net force is zero to
// round-off (not bit for bit, unlike the vertex pairs).
//
// Deterministic: the nearest points are found per vertex in parallel, each writing only its own
// record; the forces are then added serially in the order of (vertex, other cell). Across
// processes (ContactSplit) each searches for the vertices of the cells it computes, and every
// process adds everyone's records in that same order: the forces of one process, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "contact/cell_repulsion.hpp"

namespace rbcsim::contact {

// Every cell's triangles in the global vertex numbering of the contact's positions, and each
// vertex's triangles (compressed rows: vertex v's are vertex_triangles[offsets[v] ..
// offsets[v+1]]).
struct ContactSurfaces {
  std::span<const std::array<std::uint32_t, 3>> triangles;
  std::span<const std::uint32_t> vertex_triangle_offsets;
  std::span<const std::uint32_t> vertex_triangles;
};

// The nearest-point search shared between processes that hold the same positions: this process
// searches for the vertices of the cells `searches_cell` names, and `share` hands every process
// the values all of them passed (each process's in one piece, in any order of processes), as
// parallel::Communicator::gather_to_all does. The contact library stays free of MPI.
struct ContactSplit {
  std::function<bool(std::uint32_t cell)> searches_cell;
  std::function<std::vector<double>(std::span<const double>)> share;
};

// Adds the surface contact forces (force_at_contact_pN is F_half here) to forces_pN. Statistics
// as the vertex law's, counting (vertex, other cell) contacts within the range. With `split`,
// the search is shared (every process must call it, with the same positions).
ContactStatistics add_surface_contact_forces(
    std::span<const Vec3> positions_um, std::span<const std::uint32_t> owner,
    const ContactSurfaces& surfaces, const ContactParameters& parameters, const PeriodicBox& box,
    std::span<Vec3> forces_pN, ContactWorkspace& workspace, const ContactSplit* split = nullptr);

// The point of triangle (a, b, c) nearest to p, as barycentric weights of a, b, c (Ericson,
// Real-Time Collision Detection, 2005, 5.1.5).
std::array<double, 3> nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c);

}  // namespace rbcsim::contact
