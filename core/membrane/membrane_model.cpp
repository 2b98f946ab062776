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
      topology_(mesh::MeshTopology::build(mesh)),
      reference_(std::move(reference)),
      parameters_(parameters) {
  require_reference_matches(reference_, topology_);
  require_known_term_names(parameters_.forces);
  find_hinge_distribution(parameters_.distribution);  // reject an unknown name even if unused
  const auto& kernel = find_membrane_kernel(parameters_.kernel);
  for (const auto& entry : force_term_table()) {
    if (std::find(parameters_.forces.begin(), parameters_.forces.end(), entry.name) !=
        parameters_.forces.end()) {
      term_names_.push_back(entry.name);
    }
  }
  kernel_ = kernel.make(*this);
}

MembraneModel::~MembraneModel() = default;
MembraneModel::MembraneModel(MembraneModel&&) noexcept = default;
MembraneModel& MembraneModel::operator=(MembraneModel&&) noexcept = default;

MembraneWorkspace MembraneModel::make_workspace() const { return kernel_->make_workspace(*this); }

MembraneForces MembraneModel::make_forces() const {
  MembraneForces forces;
  forces.total_pN.assign(vertex_count(), Vec3::Zero());
  for (auto name : term_names_) {
    forces.terms.push_back({std::string(name), std::vector<Vec3>(vertex_count(), Vec3::Zero())});
  }
  return forces;
}

void MembraneModel::compute(std::span<const Vec3> positions_um, MembraneWorkspace& workspace,
                            MembraneForces& forces, ForceDetail detail) const {
  if (positions_um.size() != vertex_count()) {
    throw std::invalid_argument("membrane forces: " + std::to_string(positions_um.size()) +
                                " positions for a mesh of " + std::to_string(vertex_count()) +
                                " vertices");
  }
  if (forces.total_pN.size() != vertex_count() || forces.terms.size() != term_names_.size()) {
    throw std::invalid_argument("membrane forces: the force arrays were not made by this model");
  }
  kernel_->compute(*this, positions_um, workspace, forces, detail);
}

}  // namespace rbcsim::membrane
