// The membrane of one cell: the enabled force terms over its mesh and stress-free reference.
//
//   MembraneModel model(stress_free_mesh, parameters);   // reference = the initial shape
//   auto workspace = model.make_workspace();              // once; then no allocation per call
//   auto forces = model.make_forces();
//   model.compute(positions_um, workspace, forces);       // every step
//
// compute() is OpenMP-parallel and its result is bit-identical for any thread count.
#pragma once

#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/force_term.hpp"
#include "membrane/parameters.hpp"
#include "membrane/reference_state.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

// Relative deviations of the cell-level measures from the reference (whether or not their terms
// are enabled): d_V = (V - V0)/V0, d_DeltaA = (DeltaA - DeltaA0)/|DeltaA0|, d_C = (C - C0)/C0.
// d_DeltaA is not finite when DeltaA0 = 0.
struct CellDeviations {
  double volume = 0.0;
  double area_difference = 0.0;
  double total_curvature = 0.0;
};

struct MembraneForces {
  // Sum of the enabled terms per vertex, each vertex clamped to vertex_force_cap_pN, pN.
  std::vector<Vec3> total_pN;
  // One entry per enabled term, in registry order (force_terms.hpp), unclamped.
  std::vector<TermForces> terms;
  CellDeviations cell;
  // Vertices whose total force exceeded the cap in this evaluation (and were clamped).
  std::size_t capped_vertex_count = 0;

  double total_energy_pN_um() const;
  // Throws std::out_of_range for a term that is not enabled.
  const TermForces& term(std::string_view name) const;
};

class MembraneModel {
 public:
  // The stress-free mesh is the reference. Throws InputError for an unknown term or distribution
  // name, a degenerate reference, or |DeltaA0| near zero with area_difference enabled.
  MembraneModel(const mesh::TriangleMesh& stress_free_mesh, const MembraneParameters& parameters);
  // An explicit reference for this connectivity (a restart; a test that edits it). Only the
  // triangles and the vertex count of `mesh` are used.
  MembraneModel(const mesh::TriangleMesh& mesh, ReferenceState reference,
                const MembraneParameters& parameters);
  ~MembraneModel();
  MembraneModel(MembraneModel&&) noexcept;
  MembraneModel& operator=(MembraneModel&&) noexcept;

  MembraneWorkspace make_workspace() const;
  MembraneForces make_forces() const;

  // Forces at positions_um (one per vertex). Throws RuntimeFailure naming the term and element
  // when a deviation reaches its limit tau, or naming the vertex when a force is not finite.
  void compute(std::span<const Vec3> positions_um, MembraneWorkspace& workspace,
               MembraneForces& forces) const;

  std::size_t vertex_count() const { return topology_.vertex_count(); }
  std::span<const mesh::Triangle> triangles() const { return triangles_; }
  const mesh::MeshTopology& topology() const { return topology_; }
  const ReferenceState& reference() const { return reference_; }
  const MembraneParameters& parameters() const { return parameters_; }

 private:
  void cap_and_sum(MembraneForces& forces) const;

  std::vector<mesh::Triangle> triangles_;
  mesh::MeshTopology topology_;
  ReferenceState reference_;
  MembraneParameters parameters_;
  MeshStencils stencils_;
  std::vector<std::string_view> term_names_;
  std::vector<std::unique_ptr<ForceTerm>> terms_;
};

}  // namespace rbcsim::membrane
