// The reference kernel ("reference"): every enabled term evaluates itself over the whole mesh
// into its own per-vertex array (force_terms.hpp), then the arrays are summed and capped. Plain
// and readable on purpose: it defines the forces the optimised kernel must reproduce.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "membrane/force_terms.hpp"
#include "membrane/membrane_kernel.hpp"
#include "membrane/membrane_model.hpp"

namespace rbcsim::membrane {
namespace {

class ReferenceKernel final : public MembraneKernel {
 public:
  explicit ReferenceKernel(const MembraneModel& model)
      : stencils_(MeshStencils::build(model.triangles(), model.topology())),
        terms_(
            make_force_terms(model.kernel_term_names(), model.parameters(), model.reference())) {}

  MembraneWorkspace make_workspace(const MembraneModel& model) const override {
    MembraneWorkspace workspace;
    size_term_workspace(model, workspace);
    return workspace;
  }

  void compute(const MembraneModel& model, std::span<const Vec3> positions_um,
               MembraneWorkspace& workspace, MembraneForces& forces,
               ForceDetail detail) const override {
    if (workspace.geometry.edge_lengths_um.size() != model.topology().edge_count()) {
      throw std::invalid_argument("membrane forces: the workspace was not made by this model");
    }
    measure_cell_geometry(positions_um, model.triangles(), model.topology(), workspace.geometry);
    const TermContext context{positions_um, model.triangles(), model.topology(),
                              stencils_,    model.reference(), workspace.geometry};
    prepare_term_arrays(forces, model.vertex_count());
    for (std::size_t i = 0; i < terms_.size(); ++i) {
      terms_[i]->evaluate(context, workspace.scratch, forces.terms[i]);
    }
    const auto& geometry = workspace.geometry;
    forces.cell =
        cell_deviations(model.reference(), geometry.volume_um3, geometry.area_um2,
                        geometry.signed_curvature_sum_um, geometry.absolute_curvature_sum_um);
    cap_and_sum(model.parameters().vertex_force_cap_pN, terms_.size(), forces);
    if (detail == ForceDetail::totals) drop_term_detail(forces);
  }

 private:
  // The sum of the kernel's terms (the first `term_count` of forces.terms), capped.
  static void cap_and_sum(double cap_pN, std::size_t term_count, MembraneForces& forces) {
    const auto count = static_cast<std::ptrdiff_t>(forces.total_pN.size());
    std::size_t capped = 0;
    std::ptrdiff_t first_non_finite = count;
#pragma omp parallel for schedule(static) reduction(+ : capped) reduction(min : first_non_finite)
    for (std::ptrdiff_t v = 0; v < count; ++v) {
      Vec3 total = Vec3::Zero();
      for (std::size_t i = 0; i < term_count; ++i) total += forces.terms[i].forces_pN[v];
      bool finite = true;
      if (clamp_to_force_cap(total, cap_pN, finite)) ++capped;
      if (!finite) first_non_finite = std::min(first_non_finite, v);
      forces.total_pN[v] = total;
    }
    require_finite_forces(static_cast<std::size_t>(first_non_finite), forces.total_pN.size());
    forces.capped_vertex_count = capped;
  }

  MeshStencils stencils_;
  std::vector<std::unique_ptr<ForceTerm>> terms_;
};

}  // namespace

void size_term_workspace(const MembraneModel& model, MembraneWorkspace& workspace) {
  const auto edges = model.topology().edge_count();
  const auto triangles = model.topology().triangle_count();
  const auto elements = std::max(edges, triangles);
  workspace.geometry = CellGeometry(triangles, edges);
  workspace.scratch = TermScratch{std::vector<double>(elements), std::vector<double>(elements),
                                  std::vector<Vec3>(4 * edges), 0.0};
}

std::unique_ptr<MembraneKernel> make_reference_kernel(const MembraneModel& model) {
  return std::make_unique<ReferenceKernel>(model);
}

}  // namespace rbcsim::membrane
