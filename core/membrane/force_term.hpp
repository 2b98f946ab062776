// The interface of one membrane force term and what it works on. Terms are pure kernels: no
// allocation (the caller owns every array), no config, no I/O; each fills its own per-vertex
// array so the outputs can show every term separately.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/cell_geometry.hpp"
#include "membrane/reference_state.hpp"
#include "membrane/vertex_gather.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

// The three element stencils of a mesh, built once per cell. Slot numbering:
//   edge:     2 e + {0: vertex0, 1: vertex1}
//   triangle: 3 t + k (corner k)
//   hinge:    4 e + {0: vertex0, 1: vertex1, 2: wing0, 3: wing1}
struct MeshStencils {
  VertexGather edge;
  VertexGather triangle;
  VertexGather hinge;
  static MeshStencils build(std::span<const mesh::Triangle> triangles,
                            const mesh::MeshTopology& topology);
};

// Scratch arrays shared by the terms (one term at a time), sized for the mesh.
struct TermScratch {
  std::vector<double> deviations;      // d per element, max(edges, triangles) entries
  std::vector<double> energies_pN_um;  // energy per element, same size
  std::vector<Vec3> slot_forces_pN;    // one force per stencil slot, 4 * edges entries
  double cell_deviation = 0.0;         // d of a cell-level term
};

struct TermContext {
  std::span<const Vec3> positions_um;
  std::span<const mesh::Triangle> triangles;
  const mesh::MeshTopology& topology;
  const MeshStencils& stencils;
  const ReferenceState& reference;
  const CellGeometry& geometry;  // of positions_um, measured by the caller
  // Vertex velocities, um/s, for the terms that depend on them (dissipative terms, later thermal
  // noise); empty: every vertex at rest.
  std::span<const Vec3> velocities_um_per_s = {};
};

// The output of one term.
struct TermForces {
  std::string name;
  std::vector<Vec3> forces_pN;  // per vertex
  // The term's energy, sum of K energy(d) over its elements (force_law.hpp). For the `paper`
  // distribution of the angle terms it is the energy the `gradient` forces derive from (the paper
  // forces are not a gradient); it still measures how far the shape is from the reference.
  double energy_pN_um = 0.0;
  // Largest |d| over the term's elements (the cell's |d| for cell-level terms): how close the
  // shape is to the singular limit tau.
  double max_abs_deviation = 0.0;
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  // Overwrites out.forces_pN, out.energy_pN_um and out.max_abs_deviation. Throws RuntimeFailure
  // naming the term and the element when a deviation reaches its limit tau (the law is singular
  // there; the time loops treat it as an instability).
  virtual void evaluate(const TermContext& context, TermScratch& scratch,
                        TermForces& out) const = 0;
};

// Triangle t's three slots (3 t + k) of a force coefficient_pN_per_um x dA_t/dx_k
// (triangle_area_gradients_um): the corner forces of every area-based term.
void set_area_gradient_slots(const TermContext& context, std::size_t t,
                             double coefficient_pN_per_um, std::span<Vec3> slot_forces_pN);

// Scans deviations[i] for |d| >= tau in element order (the first offender is reported, whatever
// the thread count), then sets out.energy_pN_um = sum of energies and out.max_abs_deviation.
void summarize_elements(std::string_view term, std::string_view element_kind,
                        std::span<const double> deviations, std::span<const double> energies_pN_um,
                        double tau, TermForces& out);
// The same check for one cell-level deviation.
void require_within_limit(std::string_view term, std::string_view element, double deviation,
                          double tau);

}  // namespace rbcsim::membrane
