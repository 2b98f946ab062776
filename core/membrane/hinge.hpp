// A hinge: an edge with its two triangles (the paper's Fig. 4), and the two ways the three
// angle-based terms (bend, area_difference, total_curvature) push its four vertices.
//
// Vertex order everywhere: {vertex0, vertex1, wing0, wing1} as in mesh::Edge (triangle0 runs
// vertex0 -> vertex1 and contains wing0). theta is the signed dihedral angle between the outward
// normals n0, n1 (convex positive, mesh::signed_dihedral_angle_rad).
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::membrane {

struct Hinge {
  std::array<Vec3, 4> positions_um;  // vertex0, vertex1, wing0, wing1
};
Hinge hinge_of(std::span<const Vec3> positions_um, const mesh::Edge& edge);

// What one term asks of one edge; each distribution reads the part it needs.
struct HingeLoad {
  // `paper`: the signed scalar F of Eqs. 7/10/11 for this edge (negative when theta must
  // decrease), pN.
  double paper_push_pN = 0.0;
  // `gradient`: partial derivatives of the term's energy by this edge's theta (pN um per rad)
  // and by its length l (pN).
  double energy_per_angle_pN_um = 0.0;
  double energy_per_length_pN = 0.0;
};

// Gradients of theta (1/um) and of the edge length (dimensionless) by the four positions.
// theta: Bridson, Marino & Fedkiw (2003): d theta/d wing_k = -n_k / h_k (h_k: the wing's distance
// from the edge line; pushing a wing outward makes the pair less convex), and for the edge ends,
// with alpha_k = (wing_k - vertex0) . e / |e|^2 the wing's projection along e = vertex1 - vertex0:
//   d theta/d vertex0 = -(1 - alpha0) d theta/d wing0 - (1 - alpha1) d theta/d wing1
//   d theta/d vertex1 = -alpha0 d theta/d wing0 - alpha1 d theta/d wing1
// (sums to zero and has zero moment: theta is invariant under rigid motions).
struct HingeGradients {
  std::array<Vec3, 4> angle_per_um;
  std::array<Vec3, 4> length;
};
HingeGradients hinge_gradients(const Hinge& hinge);

// Forces on the four vertices (overwritten), pN.
using HingeDistribution = void (*)(const Hinge& hinge, const HingeLoad& load,
                                   std::span<Vec3, 4> forces_pN);

// `paper` (Eqs. 15-18, with Eq. 18's sign for the edge vertices so that the four forces sum to
// zero): wing k gets -F n_k, both edge vertices get +F (n0 + n1)/2, with F = paper_push_pN and
// unit normals. For F < 0 (theta too large) the wings move outward and the edge inward, which
// flattens the hinge. Conserves momentum, not angular momentum.
void distribute_as_paper(const Hinge& hinge, const HingeLoad& load, std::span<Vec3, 4> forces_pN);
// `gradient`: -(dE/dtheta grad theta + dE/dl grad l). Conserves momentum and angular momentum.
void distribute_as_gradient(const Hinge& hinge, const HingeLoad& load,
                            std::span<Vec3, 4> forces_pN);

// The registry of distributions, chosen by name (`membrane.distribution`).
struct HingeDistributionEntry {
  std::string_view name;
  HingeDistribution distribute;
};
std::span<const HingeDistributionEntry> hinge_distribution_table();
// Throws InputError naming `membrane.distribution` for an unknown name (the vertex form is not
// a per-hinge function: check is_vertex_distribution first).
HingeDistribution find_hinge_distribution(std::string_view name);

// Every form of the angle terms (`membrane.distribution`): the hinge forms of the table above and
// "vertex", the per-vertex form of vertex_patch.hpp (HemoCell 2.x).
constexpr std::string_view kVertexDistributionName = "vertex";
std::vector<std::string> distribution_names();
bool is_vertex_distribution(std::string_view name);
// Throws InputError naming `membrane.distribution` for a name that is none of them.
void require_known_distribution(std::string_view name);

}  // namespace rbcsim::membrane
