// Contact between different cells: a short-range repulsion between vertex pairs, standing in for
// the lubrication film the lattice cannot resolve (the cell-cell twin of the wall repulsion,
// cases/wall_repulsion.hpp). For vertices i, j of different cells at distance d < range_um:
//     F_ij = force_at_contact_pN * (1 - d / range_um)^2 * (x_i - x_j) / d,   F_ji = -F_ij,
// zero with zero slope at the range. The pair force is antisymmetric bit for bit (x_j - x_i is
// exactly -(x_i - x_j) in floating point), so the net force is zero to the round-off of summing.
//
// The range must exceed the membranes' edge length: a vertex can otherwise slip through the middle
// of another cell's triangle without meeting any of its vertices (setup checks it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "contact/cell_list.hpp"

namespace rbcsim::contact {

// How two cells push each other apart (suspension.contact_law).
//   vertex:  between vertex pairs, as above;
//   surface: between each vertex and the nearest point of another cell's surface
//            (surface_repulsion.hpp), along the surface's outward side.
enum class ContactLaw { vertex, surface };

// The laws' names (suspension.contact_law, result.json's contact_law), one table for both ways.
std::vector<std::string> contact_law_names();
std::string contact_law_name(ContactLaw law);
// Throws InputError naming suspension.contact_law for a name not in contact_law_names().
ContactLaw contact_law_named(std::string_view name);

struct ContactParameters {
  // vertex: the magnitude at zero distance; surface: at half the range. 0: no contact force.
  double force_at_contact_pN = 0.0;
  double range_um = 0.0;  // > 0 when the force is not 0
  ContactLaw law = ContactLaw::vertex;
  // surface: the largest push one vertex gets from one other cell. Closer than where the law
  // reaches it the push stays at the cap: the law's stiffness, (r/d)^3-steep, would otherwise
  // outgrow what the explicit coupling of membrane and fluid can integrate. Every capped push is
  // counted (ContactStatistics::capped_pushes). vertex: unused (its pair force is bounded by
  // force_at_contact_pN).
  double force_cap_pN = std::numeric_limits<double>::infinity();
};

// What one evaluation found, over all vertices.
struct ContactStatistics {
  std::size_t pairs_in_range = 0;  // ordered pairs (i, j) of different cells within the range
  std::size_t close_pairs = 0;     // of those, within a quarter of the range: near overlap
  std::size_t capped_pushes = 0;   // surface law: (vertex, other cell) pushes held at the cap
  double closest_um = std::numeric_limits<double>::infinity();
};

// What the contact keeps from one evaluation to the next, so that a step reuses its memory.
struct ContactWorkspace {
  // Per cell (a run of equal owners): its first vertex (and, last, the end), its bounding box as
  // centre and half-extent, and the other cells whose grown boxes meet its own.
  std::vector<std::size_t> cell_start;
  std::vector<Vec3> box_centre_um;
  std::vector<Vec3> box_half_um;
  std::vector<std::vector<std::uint32_t>> near_cells;
  // The vertices that lie within the range of another cell's box, ascending, with their
  // positions and owners: only they can have a partner, so only they are binned.
  std::vector<unsigned char> is_candidate;
  std::vector<std::uint32_t> candidates;
  std::vector<Vec3> candidate_positions_um;
  std::vector<std::uint32_t> candidate_owners;
  CellList list;
};

// The broad phase of both laws: in `workspace`, the vertices within `reach_um` of another cell's
// bounding box (candidates, ascending, with their positions and owners). Throws
// std::invalid_argument for owners not grouped cell by cell.
void select_candidates(std::span<const Vec3> positions_um, std::span<const std::uint32_t> owner,
                       double reach_um, const PeriodicBox& box, ContactWorkspace& workspace);

// Adds the contact forces to forces_pN (one per position). `owner[i]` is the cell of vertex i,
// the vertices grouped cell by cell (owner non-decreasing); pairs of one cell never interact (the
// membrane's own forces hold it together), and are skipped without being looked at.
// Two phases: a broad one keeps the vertices within the range of another cell's bounding box
// (boxes taken with minimum images, so a cell across a periodic seam keeps a compact box; cells
// paired by their boxes, O(cells^2), cheap beside O(vertices) up to thousands of cells); a narrow
// one bins those in the cell list, and each sums its own pairs in the list's order (a gather:
// parallel and thread-count independent). Every pair within the range has both vertices kept, so
// the pairs found are those of binning every vertex.
// Throws std::invalid_argument for mismatched sizes, ungrouped owners or a non-positive range with
// a force.
ContactStatistics add_cell_contact_forces(std::span<const Vec3> positions_um,
                                          std::span<const std::uint32_t> owner,
                                          const ContactParameters& parameters,
                                          const PeriodicBox& box, std::span<Vec3> forces_pN,
                                          ContactWorkspace& workspace);

}  // namespace rbcsim::contact
