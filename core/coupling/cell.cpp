#include "coupling/cell.hpp"

#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "ibm/transfer.hpp"
#include "membrane/edge_friction.hpp"

namespace rbcsim::coupling {

Cell::Cell(membrane::MembraneModel model, std::span<const Vec3> positions_um,
           const LatticeFrame& frame, const ibm::PointAdvanceScheme& advance_scheme)
    : model_(std::move(model)),
      workspace_(model_.make_workspace()),
      membrane_forces_(model_.make_forces()),
      advancer_(advance_scheme) {
  if (positions_um.size() != model_.vertex_count()) {
    throw std::invalid_argument("coupling: " + std::to_string(positions_um.size()) +
                                " positions for a membrane of " +
                                std::to_string(model_.vertex_count()) + " vertices");
  }
  positions_lu_.reserve(positions_um.size());
  for (const Vec3& position : positions_um) positions_lu_.push_back(frame.to_lattice(position));
  previous_positions_lu_ = positions_lu_;
  positions_um_.assign(positions_um.begin(), positions_um.end());
  const std::size_t count = positions_um.size();
  for (auto* array : {&external_forces_pN_, &total_forces_pN_, &forces_lu_, &velocities_lu_}) {
    array->assign(count, Vec3::Zero());
  }
  if (model_.has_dissipative_terms()) membrane_velocities_lu_.assign(count, Vec3::Zero());
}

Vec3 Cell::centroid_lu() const {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& position : positions_lu_) sum += position;
  return sum / static_cast<double>(positions_lu_.size());
}

void Cell::compute_membrane_forces(const LatticeFrame& frame, membrane::ForceDetail detail) {
  for (std::size_t v = 0; v < positions_lu_.size(); ++v) {
    positions_um_[v] = frame.to_um(positions_lu_[v]);
  }
  if (model_.has_dissipative_terms()) predict_membrane_velocities(frame);
  model_.compute(positions_um_, membrane_velocities_um_per_s_, workspace_, membrane_forces_,
                 detail);
  for (Vec3& force : external_forces_pN_) force.setZero();
}

void Cell::add_term_forces(const LatticeFrame&) {
  const auto& terms = membrane_forces_.terms;
  if (terms.empty() || terms.front().forces_pN.size() == vertex_count()) return;
  model_.compute(positions_um_, membrane_velocities_um_per_s_, workspace_, membrane_forces_,
                 membrane::ForceDetail::per_term);
}

void Cell::spread_forces(double lattice_force_per_pN, const ibm::DeltaKernel& kernel,
                         const ibm::GridView& grid, const std::uint8_t* solid_mask,
                         lattice::VectorField& force_density) {
  for (std::size_t v = 0; v < positions_lu_.size(); ++v) {
    total_forces_pN_[v] = membrane_forces_.total_pN[v] + external_forces_pN_[v];
    if (!total_forces_pN_[v].allFinite()) {
      throw RuntimeFailure("vertex " + std::to_string(v) + ": non-finite external force");
    }
    forces_lu_[v] = lattice_force_per_pN * total_forces_pN_[v];
  }
  stencil_.build(kernel, grid, positions_lu_, solid_mask);
  ibm::spread_forces(stencil_, forces_lu_, grid, force_density[0].data(), force_density[1].data(),
                     force_density[2].data());
}

void Cell::interpolate_and_advance(const ibm::GridView& grid, const lattice::VectorField& velocity) {
  ibm::interpolate_velocity(stencil_, grid, velocity[0].data(), velocity[1].data(),
                            velocity[2].data(), velocities_lu_);
  if (model_.has_dissipative_terms()) lend_masses();
  previous_positions_lu_ = positions_lu_;
  advancer_.advance(positions_lu_, velocities_lu_);
}

void Cell::lend_masses() {
  // A force spread from a vertex moves the fluid at every node of its stencil, and so the
  // interpolated velocity of every vertex whose stencil shares those nodes. Over a smooth pattern
  // of forces the response of vertex i is sum_n w_in sum_j w_jn: the unit spread from all the
  // cell's vertices and interpolated back, the largest response any pattern gets in one step (its
  // row sum). The mass lent is kLentMassFraction of its inverse: the implicit step must not
  // underestimate the fluid's response by more than a factor of 2 (predict_membrane_velocities),
  // and over the steps a force acts the fluid's response to a smooth pattern grows beyond the
  // one-step estimate (measured: unstable at 1 and 1/2 of it in a sheared capsule at the red
  // cell's membrane viscosity, stable at 1/5; tests/coupling/shear_rotation_test.cpp).
  constexpr double kLentMassFraction = 0.2;
  if (weight_density_.size() < ibm::node_count(stencil_.grid())) {
    weight_density_.assign(ibm::node_count(stencil_.grid()), 0.0);
  }
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    const auto nodes = stencil_.nodes(v);
    const auto weights = stencil_.weights(v);
    for (std::size_t k = 0; k < nodes.size(); ++k) weight_density_[nodes[k]] += weights[k];
  }
  lent_masses_.resize(vertex_count());
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    const auto nodes = stencil_.nodes(v);
    const auto weights = stencil_.weights(v);
    double response = 0.0;
    for (std::size_t k = 0; k < nodes.size(); ++k) response += weights[k] * weight_density_[nodes[k]];
    lent_masses_[v] = kLentMassFraction / response;
  }
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    for (const auto node : stencil_.nodes(v)) weight_density_[node] = 0.0;
  }
}

void Cell::predict_membrane_velocities(const LatticeFrame& frame) {
  if (!lent_masses_.empty()) {  // none before the first step: at rest, no friction
    // The friction in lattice force per lattice velocity: gamma pN/(um/s) times (dx/dt um/s per
    // lattice velocity) times (lattice force per pN).
    const double per_pN_s_per_um = frame.dx_um / frame.dt_s * frame.lattice_force_per_pN;
    const auto& friction = model_.edge_friction();
    const membrane::EdgeFrictionParameters friction_lu{
        friction.central_pN_s_per_um * per_pN_s_per_um,
        friction.tangential_pN_s_per_um * per_pN_s_per_um};
    // Started from the previous step's solution.
    friction_iterations_ = membrane::solve_implicit_friction(
        positions_lu_, lent_masses_, velocities_lu_, membrane::EdgeNetwork::of(model_.topology()),
        friction_lu, membrane_velocities_lu_, {.relative_tolerance = kFrictionTolerance});
  }
  const double um_per_s_per_lu = frame.dx_um / frame.dt_s;
  membrane_velocities_um_per_s_.resize(vertex_count());
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    membrane_velocities_um_per_s_[v] = um_per_s_per_lu * membrane_velocities_lu_[v];
  }
}

void Cell::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "positions_lu", positions_lu_);
  archive.put(prefix + "previous_positions_lu", previous_positions_lu_);
  archive.put(prefix + "velocities_lu", velocities_lu_);
  if (model_.has_dissipative_terms()) {
    archive.put(prefix + "membrane_velocities_lu", membrane_velocities_lu_);
    archive.put(prefix + "lent_masses", lent_masses_);
  }
  advancer_.save_state(archive, prefix);
}

void Cell::restore_state(StateArchive& archive, const std::string& prefix,
                         const LatticeFrame& frame) {
  archive.take(prefix + "positions_lu", positions_lu_);
  archive.take(prefix + "previous_positions_lu", previous_positions_lu_);
  archive.take(prefix + "velocities_lu", velocities_lu_);
  if (model_.has_dissipative_terms()) {
    archive.take(prefix + "membrane_velocities_lu", membrane_velocities_lu_);
    lent_masses_ = archive.take(prefix + "lent_masses", std::nullopt);
  }
  advancer_.restore_state(archive, prefix, vertex_count());
  // Where the next step computes the forces; until then, what positions_um() shows.
  for (std::size_t v = 0; v < vertex_count(); ++v) positions_um_[v] = frame.to_um(positions_lu_[v]);
}

}  // namespace rbcsim::coupling
