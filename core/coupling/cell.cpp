#include "coupling/cell.hpp"

#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "ibm/transfer.hpp"

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
}

Vec3 Cell::centroid_lu() const {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& position : positions_lu_) sum += position;
  return sum / static_cast<double>(positions_lu_.size());
}

void Cell::compute_membrane_forces(const LatticeFrame& frame) {
  for (std::size_t v = 0; v < positions_lu_.size(); ++v) {
    positions_um_[v] = frame.to_um(positions_lu_[v]);
  }
  model_.compute(positions_um_, workspace_, membrane_forces_);
  for (Vec3& force : external_forces_pN_) force.setZero();
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

void Cell::interpolate_and_advance(const ibm::GridView& grid,
                                   const lattice::VectorField& velocity) {
  ibm::interpolate_velocity(stencil_, grid, velocity[0].data(), velocity[1].data(),
                            velocity[2].data(), velocities_lu_);
  previous_positions_lu_ = positions_lu_;
  advancer_.advance(positions_lu_, velocities_lu_);
}

void Cell::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "positions_lu", positions_lu_);
  archive.put(prefix + "previous_positions_lu", previous_positions_lu_);
  archive.put(prefix + "velocities_lu", velocities_lu_);
  advancer_.save_state(archive, prefix);
}

void Cell::restore_state(StateArchive& archive, const std::string& prefix,
                         const LatticeFrame& frame) {
  archive.take(prefix + "positions_lu", positions_lu_);
  archive.take(prefix + "previous_positions_lu", previous_positions_lu_);
  archive.take(prefix + "velocities_lu", velocities_lu_);
  advancer_.restore_state(archive, prefix, vertex_count());
  // Where the next step computes the forces; until then, what positions_um() shows.
  for (std::size_t v = 0; v < vertex_count(); ++v) positions_um_[v] = frame.to_um(positions_lu_[v]);
}

}  // namespace rbcsim::coupling
