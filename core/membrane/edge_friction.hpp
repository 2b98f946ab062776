// Membrane viscosity as friction on the edges (Fedosov, Caswell & Karniadakis, Biophys. J.
// 98:2215, 2010; docs/physics.md, "Membrane viscosity"): each edge ij resists the relative
// velocity of its two vertices,
//   F_i = -gamma_T v_ij - gamma_C (v_ij . e_ij) e_ij,   F_j = -F_i,   v_ij = v_i - v_j,
// e_ij the unit edge. Pairwise, so momentum is conserved exactly; with gamma_T = 0 the force is
// central and conserves angular momentum too, and a rigid motion feels none. The dissipated power
// sum_e gamma_T |v_ij|^2 + gamma_C (v_ij . e_ij)^2 is never negative.
//
// On a regular triangular network under a uniform in-plane velocity gradient G (strain rate
// D, spin W) the power per area is sqrt3 gamma_T (D:D + W:W) + (sqrt3 gamma_C / 4)(2 D:D +
// (tr D)^2): a 2D Newtonian membrane of shear viscosity eta_m = sqrt3 gamma_T + sqrt3 gamma_C / 4
// in simple shear (Fedosov's relation) and, with gamma_T = 0, dilatational viscosity 2 eta_m.
//
// Units: velocities um/s, forces pN, gamma pN s/um; 1 pN s/um = 1e-6 N s/m = 1 Pa s um, the
// unit of the 2D membrane viscosity (membrane.viscosity_Pa_s_um).
#pragma once

#include <cstddef>
#include <Eigen/Dense>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "common/registry.hpp"
#include "common/vec3.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::membrane {

struct EdgeFrictionParameters {
  double central_pN_s_per_um = 0.0;     // gamma_C, along the edge
  double tangential_pN_s_per_um = 0.0;  // gamma_T, on the whole relative velocity
};

// How a 2D membrane viscosity eta_m is shared between gamma_C and gamma_T, chosen by name
// (`membrane.viscosity_split`). Both give eta_m = sqrt3 gamma_T + sqrt3 gamma_C / 4.
struct ViscositySplit {
  std::string_view name;
  std::string_view description;
  EdgeFrictionParameters (*split)(double viscosity_Pa_s_um);
};
const Registry<ViscositySplit>& viscosity_splits();

// The friction of `viscosity_Pa_s_um` shared as the named split says (InputError naming
// `membrane.viscosity_split` for an unknown name).
EdgeFrictionParameters edge_friction_for(double viscosity_Pa_s_um, std::string_view split);

// The edges the friction acts on and each vertex's edges (compressed rows: vertex v's edges are
// vertex_edges[vertex_edge_offsets[v] .. vertex_edge_offsets[v + 1]]); only Edge::vertex0 and
// vertex1 are read, so an open patch can be described as well as a cell's MeshTopology.
struct EdgeNetwork {
  std::span<const mesh::Edge> edges;
  std::span<const std::int32_t> vertex_edge_offsets;
  std::span<const std::int32_t> vertex_edges;
  std::size_t vertex_count() const { return vertex_edge_offsets.size() - 1; }
  static EdgeNetwork of(const mesh::MeshTopology& topology) {
    return {topology.edges(), topology.vertex_edge_offsets(), topology.vertex_edges()};
  }
};

// Overwrites forces[v] with the friction force on every vertex at `velocities` (any one unit of
// velocity; the forces are then gamma times it). Edges in topology order, each vertex summing its
// edges in a fixed order: the result does not depend on the thread count. `positions` only give
// the edge directions (any length unit).
void edge_friction_forces(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                          const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                          std::span<Vec3> forces);

// The power the friction dissipates at `velocities`: -sum_v F_v . v_v (>= 0), summed in edge
// order.
double edge_friction_power(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                           const EdgeNetwork& network, const EdgeFrictionParameters& friction);

// For repeated products at one configuration (an implicit solve): the edges' unit axes, and
// Gamma v, the friction that relative velocities v meet (minus the friction force), ADDED to
// `out` edge by edge in edge order (serial), and each vertex's 3x3 diagonal block of Gamma
// (sum over its edges of gamma_T I + gamma_C e e^T), added to `blocks`.
std::vector<Vec3> edge_axes(std::span<const Vec3> positions, const EdgeNetwork& network);
void add_friction_resistance(std::span<const Vec3> axes, std::span<const Vec3> velocities,
                             const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                             std::span<Vec3> out);
void add_friction_diagonal(std::span<const Vec3> axes, const EdgeNetwork& network,
                           const EdgeFrictionParameters& friction,
                           std::span<Eigen::Matrix3d> blocks);

}  // namespace rbcsim::membrane
