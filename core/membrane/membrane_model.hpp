// The membrane of one cell: the enabled force terms over its mesh and stress-free reference.
//
//   MembraneModel model(stress_free_mesh, parameters);   // reference = the initial shape
//   auto workspace = model.make_workspace();              // once; then no allocation per call
//   auto forces = model.make_forces();
//   model.compute(positions_um, workspace, forces, ForceDetail::totals);  // every step
//   model.compute(positions_um, workspace, forces);       // output steps: per-term arrays too
//
// compute() is OpenMP-parallel and its result is bit-identical for any thread count. The kernel
// that computes it is chosen by name (MembraneParameters::kernel, membrane_kernel.hpp).
#pragma once

#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/edge_friction.hpp"
#include "membrane/force_term.hpp"
#include "membrane/membrane_forces.hpp"
#include "membrane/membrane_kernel.hpp"
#include "membrane/parameters.hpp"
#include "membrane/reference_state.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane {

class MembraneModel {
 public:
  // The stress-free mesh is the reference. Throws InputError for an unknown term, distribution
  // or kernel name, a degenerate reference, or |DeltaA0| near zero with area_difference enabled.
  MembraneModel(const mesh::TriangleMesh& stress_free_mesh, const MembraneParameters& parameters);
  // An explicit reference for this connectivity (a restart; a test that edits it). Only the
  // triangles and the vertex count of `mesh` are used.
  MembraneModel(const mesh::TriangleMesh& mesh, ReferenceState reference,
                const MembraneParameters& parameters);
  ~MembraneModel();
  MembraneModel(MembraneModel&&) noexcept;
  MembraneModel& operator=(MembraneModel&&) noexcept;

  // Replaces the stress-free reference (same connectivity), e.g. with a scaled one as a cell
  // grows (scaled_reference); the triangles and topology stay where they are, the kernel is rebuilt
  // (make workspaces again). Throws as the constructor does for a reference that does not fit.
  void set_reference(ReferenceState reference);

  MembraneWorkspace make_workspace() const;
  MembraneForces make_forces() const;

  // Forces at positions_um (one per vertex); `detail` says whether the per-term arrays and
  // energies are wanted too (membrane_forces.hpp). Throws RuntimeFailure naming the term and
  // element when a deviation reaches its limit tau, or naming the vertex when a force is not
  // finite. `workspace` must come from this model's make_workspace(). The elastic terms come from
  // the kernel, summed and capped; the dissipative ones (membrane viscosity) are evaluated at
  // `velocities_um_per_s` (one per vertex, or empty: at rest) and added after the cap.
  void compute(std::span<const Vec3> positions_um, std::span<const Vec3> velocities_um_per_s,
               MembraneWorkspace& workspace, MembraneForces& forces,
               ForceDetail detail = ForceDetail::per_term) const;
  // At rest: the elastic forces only (a dissipative term contributes none).
  void compute(std::span<const Vec3> positions_um, MembraneWorkspace& workspace,
               MembraneForces& forces, ForceDetail detail = ForceDetail::per_term) const {
    compute(positions_um, {}, workspace, forces, detail);
  }

  std::size_t vertex_count() const { return topology_->vertex_count(); }
  std::span<const mesh::Triangle> triangles() const { return triangles_; }
  // Stays at its address when the model is moved (a Cell in a growing vector): the volume hold
  // and the sub-spacing drag keep measures that point to it.
  const mesh::MeshTopology& topology() const { return *topology_; }
  const ReferenceState& reference() const { return reference_; }
  const MembraneParameters& parameters() const { return parameters_; }
  // The enabled terms in registry order: the order of MembraneForces::terms.
  std::span<const std::string_view> enabled_term_names() const { return term_names_; }
  // The elastic ones, which the kernel computes: the first entries of enabled_term_names().
  std::span<const std::string_view> kernel_term_names() const {
    return std::span(term_names_).first(kernel_term_count_);
  }
  // Whether a dissipative term (membrane viscosity) is enabled: the forces then depend on the
  // vertex velocities.
  bool has_dissipative_terms() const { return kernel_term_count_ < term_names_.size(); }
  // The friction of the enabled viscosity term (zero without it), for the implicit update of a
  // coupling (edge_friction.hpp).
  const EdgeFrictionParameters& edge_friction() const { return friction_; }

 private:
  // The parts built from the reference: the kernel and the dissipative terms.
  void build_reference_terms();
  void add_dissipative_forces(std::span<const Vec3> positions_um,
                              std::span<const Vec3> velocities_um_per_s,
                              MembraneWorkspace& workspace, MembraneForces& forces,
                              ForceDetail detail) const;

  std::vector<mesh::Triangle> triangles_;
  std::unique_ptr<const mesh::MeshTopology> topology_;
  ReferenceState reference_;
  MembraneParameters parameters_;
  std::vector<std::string_view> term_names_;
  std::size_t kernel_term_count_ = 0;
  EdgeFrictionParameters friction_;
  std::unique_ptr<MembraneKernel> kernel_;
  // The dissipative terms, evaluated by compute() itself (built only when enabled).
  std::vector<std::unique_ptr<ForceTerm>> dissipative_terms_;
  std::unique_ptr<MeshStencils> stencils_;
};

}  // namespace rbcsim::membrane
