// The per-vertex form of the three angle terms (`membrane.distribution = vertex`): the way
// HemoCell 2.x (RbcHighOrderModel, its "per-vertex bending force") pushes a cell's bending-like
// forces, as a reproduction variant beside the paper's per-edge Eqs. 15-18 and the exact gradient.
//
// Each vertex i has a patch: its ring of n_i neighbours and its patch normal n_i, the normalised
// sum of the unit outward normals of its triangles. Its offset
//   M_i = n_i . (x_i - m_i),  m_i the centroid of the ring,
// is positive where the membrane bulges outward at i (convex) and is a discrete mean curvature
// times the squared edge (M = a^2 / (2 R) on a sphere of radius R with edges a, to leading order).
// A term gives every vertex a push P_i (pN) and the force is
//   P_i n_i on vertex i,   -P_i n_i / n_i on each of its n_i ring neighbours,
// so each patch's forces sum to zero (momentum is conserved; angular momentum is not, as in the
// paper's form). A positive push raises i above its ring: it makes the patch more convex.
#pragma once

#include <cstdint>
#include <span>

#include "common/vec3.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

// Unit patch normals and offsets M_i (um) of every vertex (spans sized vertex_count()).
void measure_vertex_patches(std::span<const Vec3> positions_um,
                            std::span<const mesh::Triangle> triangles,
                            const mesh::MeshTopology& topology, std::span<Vec3> normals,
                            std::span<double> offsets_um);

// The forces (overwritten, pN) of the pushes pushes_pN[i] along the patch normals, gathered per
// vertex (vertex i's own push minus its neighbours' shares), so the result does not depend on the
// thread count.
void gather_vertex_pushes(const mesh::MeshTopology& topology, std::span<const Vec3> normals,
                          std::span<const double> pushes_pN, std::span<Vec3> forces_pN);

}  // namespace rbcsim::membrane
