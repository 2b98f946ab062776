#include "membrane/membrane_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "membrane/force_terms.hpp"

namespace rbcsim::membrane {
namespace {

void require_known_term_names(const std::vector<std::string>& names) {
  std::string known;
  for (const auto& entry : force_term_table()) {
    known += (known.empty() ? "" : ", ") + std::string(entry.name);
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto& table = force_term_table();
    if (std::none_of(table.begin(), table.end(),
                     [&](const ForceTermEntry& entry) { return entry.name == names[i]; })) {
      throw InputError("membrane.forces",
                       "unknown force term '" + names[i] + "' (known: " + known + ")");
    }
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
        names.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw InputError("membrane.forces", "force term '" + names[i] + "' is listed twice");
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

double MembraneForces::total_energy_pN_um() const {
  double energy = 0.0;
  for (const auto& term : terms) energy += term.energy_pN_um;
  return energy;
}

const TermForces& MembraneForces::term(std::string_view name) const {
  for (const auto& term : terms) {
    if (term.name == name) return term;
  }
  throw std::out_of_range("membrane force term '" + std::string(name) + "' is not enabled");
}

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
      parameters_(parameters),
      stencils_(MeshStencils::build(triangles_, topology_)) {
  require_reference_matches(reference_, topology_);
  require_known_term_names(parameters_.forces);
  find_hinge_distribution(parameters_.distribution);  // reject an unknown name even if unused
  for (const auto& entry : force_term_table()) {
    if (std::find(parameters_.forces.begin(), parameters_.forces.end(), entry.name) ==
        parameters_.forces.end()) {
      continue;
    }
    term_names_.push_back(entry.name);
    terms_.push_back(entry.make(parameters_, reference_));
  }
}

MembraneModel::~MembraneModel() = default;
MembraneModel::MembraneModel(MembraneModel&&) noexcept = default;
MembraneModel& MembraneModel::operator=(MembraneModel&&) noexcept = default;

MembraneWorkspace MembraneModel::make_workspace() const {
  const auto edges = topology_.edge_count();
  const auto triangles = topology_.triangle_count();
  const auto elements = std::max(edges, triangles);
  return {CellGeometry(triangles, edges),
          TermScratch{std::vector<double>(elements), std::vector<double>(elements),
                      std::vector<Vec3>(4 * edges), 0.0}};
}

MembraneForces MembraneModel::make_forces() const {
  MembraneForces forces;
  forces.total_pN.assign(vertex_count(), Vec3::Zero());
  for (auto name : term_names_) {
    forces.terms.push_back({std::string(name), std::vector<Vec3>(vertex_count(), Vec3::Zero())});
  }
  return forces;
}

void MembraneModel::compute(std::span<const Vec3> positions_um, MembraneWorkspace& workspace,
                            MembraneForces& forces) const {
  if (positions_um.size() != vertex_count()) {
    throw std::invalid_argument("membrane forces: " + std::to_string(positions_um.size()) +
                                " positions for a mesh of " + std::to_string(vertex_count()) +
                                " vertices");
  }
  measure_cell_geometry(positions_um, triangles_, topology_, workspace.geometry);
  const TermContext context{positions_um, triangles_, topology_,
                            stencils_,    reference_, workspace.geometry};
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    terms_[i]->evaluate(context, workspace.scratch, forces.terms[i]);
  }
  const auto& geometry = workspace.geometry;
  forces.cell = {(geometry.volume_um3 - reference_.volume_um3) / reference_.volume_um3,
                 (geometry.signed_curvature_sum_um - reference_.signed_curvature_sum_um) /
                     std::abs(reference_.signed_curvature_sum_um),
                 (geometry.absolute_curvature_sum_um - reference_.absolute_curvature_sum_um) /
                     reference_.absolute_curvature_sum_um};
  cap_and_sum(forces);
}

void MembraneModel::cap_and_sum(MembraneForces& forces) const {
  const double cap_pN = parameters_.vertex_force_cap_pN;
  const auto count = static_cast<std::ptrdiff_t>(vertex_count());
  std::size_t capped = 0;
  std::ptrdiff_t first_non_finite = count;
#pragma omp parallel for schedule(static) reduction(+ : capped) reduction(min : first_non_finite)
  for (std::ptrdiff_t v = 0; v < count; ++v) {
    Vec3 total = Vec3::Zero();
    for (const auto& term : forces.terms) total += term.forces_pN[v];
    const double magnitude_pN = total.norm();
    if (!std::isfinite(magnitude_pN)) first_non_finite = std::min(first_non_finite, v);
    if (magnitude_pN > cap_pN) {
      total *= cap_pN / magnitude_pN;
      ++capped;
    }
    forces.total_pN[v] = total;
  }
  if (first_non_finite < count) {
    throw RuntimeFailure("membrane forces: the force on vertex " +
                         std::to_string(first_non_finite) + " is not finite (unstable state)");
  }
  forces.capped_vertex_count = capped;
}

}  // namespace rbcsim::membrane
