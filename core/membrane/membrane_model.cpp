#include "membrane/membrane_model.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "membrane/force_terms.hpp"

namespace rbcsim::membrane {
namespace {

void require_known_term_names(const std::vector<std::string>& names) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    force_term_registry().find(names[i], "membrane.forces");
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
        names.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw InputError("membrane.forces", in_quotes(names[i]) + " is listed twice");
    }
  }
}

void require_reference_matches(const ReferenceState& reference,
                               const mesh::MeshTopology& topology) {
  const auto edges = topology.edge_count();
  const auto triangles = topology.triangle_count();
  if (reference.edge_lengths_um.size() != edges || reference.dihedral_angles_rad.size() != edges ||
      reference.triangle_areas_um2.size() != triangles ||
      reference.triangle_perimeters_um.size() != triangles) {
    throw std::invalid_argument("membrane reference state does not match the mesh (" +
                                std::to_string(edges) + " edges, " + std::to_string(triangles) +
                                " triangles)");
  }
}

// The per-vertex form reads a patch offset per vertex.
void require_vertex_offsets(const ReferenceState& reference, const mesh::MeshTopology& topology,
                            const std::string& distribution) {
  if (is_vertex_distribution(distribution) &&
      reference.vertex_offsets_um.size() != topology.vertex_count()) {
    throw std::invalid_argument("membrane reference state has no patch offset per vertex (" +
                                std::to_string(topology.vertex_count()) +
                                " vertices), which the vertex form needs");
  }
}

}  // namespace

MembraneModel::MembraneModel(const mesh::TriangleMesh& stress_free_mesh,
                             const MembraneParameters& parameters)
    : MembraneModel(
          stress_free_mesh,
          capture_reference_state(stress_free_mesh.positions_um, stress_free_mesh.triangles,
                                  mesh::MeshTopology::build(stress_free_mesh)),
          parameters) {}

MembraneModel::MembraneModel(const mesh::TriangleMesh& mesh, ReferenceState reference,
                             const MembraneParameters& parameters)
    : triangles_(mesh.triangles),
      topology_(std::make_unique<const mesh::MeshTopology>(mesh::MeshTopology::build(mesh))),
      reference_(std::move(reference)),
      parameters_(parameters) {
  require_reference_matches(reference_, *topology_);
  require_known_term_names(parameters_.forces);
  require_known_distribution(parameters_.distribution);  // reject an unknown name even if unused
  require_vertex_offsets(reference_, *topology_, parameters_.distribution);
  find_membrane_kernel(parameters_.kernel);  // an unknown name fails before the terms are built
  auto enabled = [&](const ForceTermEntry& entry) {
    return std::find(parameters_.forces.begin(), parameters_.forces.end(), entry.name) !=
           parameters_.forces.end();
  };
  // Elastic terms first, then the dissipative ones (registry order within each).
  for (const bool dissipative : {false, true}) {
    for (const auto& entry : force_term_table()) {
      if (entry.dissipative == dissipative && enabled(entry)) term_names_.push_back(entry.name);
    }
    if (!dissipative) kernel_term_count_ = term_names_.size();
  }
  if (has_dissipative_terms()) {
    stencils_ = std::make_unique<MeshStencils>(MeshStencils::build(triangles_, *topology_));
  }
  if (std::find(term_names_.begin(), term_names_.end(), "viscosity") != term_names_.end()) {
    friction_ = edge_friction_for(parameters_.viscosity_Pa_s_um, parameters_.viscosity_split);
  }
  build_reference_terms();
}

void MembraneModel::build_reference_terms() {
  if (has_dissipative_terms()) {
    const auto names = std::span(term_names_).subspan(kernel_term_count_);
    dissipative_terms_ = make_force_terms(names, parameters_, reference_);
  }
  kernel_ = find_membrane_kernel(parameters_.kernel).make(*this);
}

void MembraneModel::set_reference(ReferenceState reference) {
  require_reference_matches(reference, *topology_);
  require_vertex_offsets(reference, *topology_, parameters_.distribution);
  reference_ = std::move(reference);
  build_reference_terms();
}

MembraneModel::~MembraneModel() = default;
MembraneModel::MembraneModel(MembraneModel&&) noexcept = default;
MembraneModel& MembraneModel::operator=(MembraneModel&&) noexcept = default;

MembraneWorkspace MembraneModel::make_workspace() const {
  auto workspace = kernel_->make_workspace(*this);
  if (has_dissipative_terms()) {
    const auto edges = topology_->edge_count();
    const auto triangles = topology_->triangle_count();
    const auto elements = std::max(edges, triangles);
    workspace.dissipative_geometry = CellGeometry(triangles, edges);
    workspace.dissipative_scratch = TermScratch{std::vector<double>(elements),
                                                std::vector<double>(elements),
                                                std::vector<Vec3>(4 * edges), 0.0};
    for (auto name : std::span(term_names_).subspan(kernel_term_count_)) {
      workspace.dissipative.push_back(
          {std::string(name), std::vector<Vec3>(vertex_count(), Vec3::Zero())});
    }
  }
  return workspace;
}

MembraneForces MembraneModel::make_forces() const {
  MembraneForces forces;
  forces.total_pN.assign(vertex_count(), Vec3::Zero());
  for (auto name : term_names_) {
    forces.terms.push_back({std::string(name), std::vector<Vec3>(vertex_count(), Vec3::Zero())});
  }
  return forces;
}

void MembraneModel::compute(std::span<const Vec3> positions_um,
                            std::span<const Vec3> velocities_um_per_s,
                            MembraneWorkspace& workspace, MembraneForces& forces,
                            ForceDetail detail) const {
  if (positions_um.size() != vertex_count()) {
    throw std::invalid_argument("membrane forces: " + std::to_string(positions_um.size()) +
                                " positions for a mesh of " + std::to_string(vertex_count()) +
                                " vertices");
  }
  if (forces.total_pN.size() != vertex_count() || forces.terms.size() != term_names_.size()) {
    throw std::invalid_argument("membrane forces: the force arrays were not made by this model");
  }
  if (!velocities_um_per_s.empty() && velocities_um_per_s.size() != vertex_count()) {
    throw std::invalid_argument("membrane forces: " + std::to_string(velocities_um_per_s.size()) +
                                " velocities for a mesh of " + std::to_string(vertex_count()) +
                                " vertices");
  }
  kernel_->compute(*this, positions_um, workspace, forces, detail);
  if (!has_dissipative_terms()) return;
  if (!velocities_um_per_s.empty()) {
    add_dissipative_forces(positions_um, velocities_um_per_s, workspace, forces, detail);
    return;
  }
  // At rest a dissipative term exerts nothing: no evaluation, only its (zero) output.
  for (std::size_t i = kernel_term_count_; i < forces.terms.size(); ++i) {
    auto& term = forces.terms[i];
    term.max_abs_deviation = 0.0;
    if (detail == ForceDetail::per_term) {
      std::fill(term.forces_pN.begin(), term.forces_pN.end(), Vec3::Zero());
      term.energy_pN_um = 0.0;
    }
  }
}

void MembraneModel::add_dissipative_forces(std::span<const Vec3> positions_um,
                                           std::span<const Vec3> velocities_um_per_s,
                                           MembraneWorkspace& workspace, MembraneForces& forces,
                                           ForceDetail detail) const {
  if (workspace.dissipative.size() != dissipative_terms_.size()) {
    throw std::invalid_argument("membrane forces: the workspace was not made by this model");
  }
  measure_cell_geometry(positions_um, triangles_, *topology_, workspace.dissipative_geometry);
  TermContext context{positions_um, triangles_, *topology_, *stencils_, reference_,
                      workspace.dissipative_geometry};
  context.velocities_um_per_s = velocities_um_per_s;
  for (std::size_t i = 0; i < dissipative_terms_.size(); ++i) {
    auto& out = workspace.dissipative[i];
    dissipative_terms_[i]->evaluate(context, workspace.dissipative_scratch, out);
    for (std::size_t v = 0; v < vertex_count(); ++v) {
      if (!out.forces_pN[v].allFinite()) {
        throw RuntimeFailure("membrane term '" + out.name + "': vertex " + std::to_string(v) +
                             ": the force is not finite");
      }
      forces.total_pN[v] += out.forces_pN[v];
    }
    auto& term = forces.terms[kernel_term_count_ + i];
    term.max_abs_deviation = out.max_abs_deviation;
    if (detail == ForceDetail::per_term) {
      term.forces_pN = out.forces_pN;
      term.energy_pN_um = out.energy_pN_um;
    }
  }
}

}  // namespace rbcsim::membrane
