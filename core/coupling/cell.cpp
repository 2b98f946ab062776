#include "coupling/cell.hpp"

#include <algorithm>
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
  // No velocities: the membrane's friction acts through solve_membrane_friction, not through
  // the force spread.
  model_.compute(positions_um_, workspace_, membrane_forces_, detail);
  for (Vec3& force : external_forces_pN_) force.setZero();
}

namespace {

constexpr std::size_t kForceHeaderValues = 5;     // capped count, four deviations
constexpr std::size_t kForceValuesPerVertex = 6;  // membrane total, external

}  // namespace

void Cell::append_forces(std::vector<double>& values) const {
  const auto& deviations = membrane_forces_.cell;
  values.insert(values.end(),
                {static_cast<double>(membrane_forces_.capped_vertex_count), deviations.volume,
                 deviations.total_area, deviations.area_difference, deviations.total_curvature});
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    const Vec3& total = membrane_forces_.total_pN[v];
    const Vec3& external = external_forces_pN_[v];
    values.insert(values.end(),
                  {total.x(), total.y(), total.z(), external.x(), external.y(), external.z()});
  }
}

std::span<const double> Cell::adopt_forces(std::span<const double> values,
                                           const LatticeFrame& frame) {
  const std::size_t count = kForceHeaderValues + kForceValuesPerVertex * vertex_count();
  if (values.size() < count) {
    throw std::invalid_argument("Cell::adopt_forces: " + std::to_string(values.size()) +
                                " values for " + std::to_string(count));
  }
  for (std::size_t v = 0; v < positions_lu_.size(); ++v) {
    positions_um_[v] = frame.to_um(positions_lu_[v]);
  }
  membrane_forces_.capped_vertex_count = static_cast<std::size_t>(values[0]);
  membrane_forces_.cell = {values[1], values[2], values[3], values[4]};
  membrane::drop_term_detail(membrane_forces_);
  const double* at = values.data() + kForceHeaderValues;
  for (std::size_t v = 0; v < vertex_count(); ++v, at += kForceValuesPerVertex) {
    membrane_forces_.total_pN[v] = Vec3(at[0], at[1], at[2]);
    external_forces_pN_[v] = Vec3(at[3], at[4], at[5]);
  }
  return values.subspan(count);
}

void Cell::add_term_forces(const LatticeFrame& frame) {
  const auto& terms = membrane_forces_.terms;
  if (terms.empty() || terms.front().forces_pN.size() == vertex_count()) return;
  if (!model_.has_dissipative_terms()) {
    model_.compute(positions_um_, workspace_, membrane_forces_, membrane::ForceDetail::per_term);
    return;
  }
  // With the friction at the velocities of the latest implicit step, so that the output shows it.
  const double um_per_s_per_lu = frame.dx_um / frame.dt_s;
  std::vector<Vec3> velocities_um_per_s(vertex_count());
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    velocities_um_per_s[v] = um_per_s_per_lu * membrane_velocities_lu_[v];
  }
  model_.compute(positions_um_, velocities_um_per_s, workspace_, membrane_forces_,
                 membrane::ForceDetail::per_term);
}

void Cell::prepare_spread(double lattice_force_per_pN, const ibm::DeltaKernel& kernel,
                          const ibm::GridView& grid, const std::uint8_t* solid_mask) {
  for (std::size_t v = 0; v < positions_lu_.size(); ++v) {
    total_forces_pN_[v] = membrane_forces_.total_pN[v] + external_forces_pN_[v];
    if (!total_forces_pN_[v].allFinite()) {
      throw RuntimeFailure("vertex " + std::to_string(v) + ": non-finite external force");
    }
    forces_lu_[v] = lattice_force_per_pN * total_forces_pN_[v];
  }
  stencil_.build(kernel, grid, positions_lu_, solid_mask);
}

bool Cell::has_membrane_friction() const {
  const auto& friction = model_.edge_friction();
  return friction.central_pN_s_per_um > 0.0 || friction.tangential_pN_s_per_um > 0.0;
}

membrane::EdgeFrictionParameters Cell::friction_lu(const LatticeFrame& frame) const {
  // gamma pN/(um/s) times (dx/dt um/s per lattice velocity) times (lattice force per pN).
  const double per_pN_s_per_um = frame.dx_um / frame.dt_s * frame.lattice_force_per_pN;
  const auto& friction = model_.edge_friction();
  return {friction.central_pN_s_per_um * per_pN_s_per_um,
          friction.tangential_pN_s_per_um * per_pN_s_per_um};
}

LatestForce Cell::latest_force(const std::array<double, 3>& body_force_lu) const {
  return {forces_lu_, Vec3(body_force_lu[0], body_force_lu[1], body_force_lu[2])};
}

ImplicitFrictionSettings Cell::friction_settings() const {
  return {.relative_tolerance = model_.parameters().viscosity_solve_tolerance};
}

void Cell::solve_membrane_friction(const lattice::FluidSolver& fluid, const LatticeFrame& frame,
                                   std::size_t time_step) {
  if (!has_membrane_friction() || !fluid.populations_natural()) return;
  // Every step the populations are natural (reference kernel), every second step otherwise
  // (the optimised kernel's AA pattern): each step covers the steps since the previous one.
  const auto dt_steps = static_cast<double>(time_step - last_friction_step_);
  friction_iterations_ = friction_.solve(
      stencil_, positions_lu_, membrane::EdgeNetwork::of(model_.topology()), friction_lu(frame),
      dt_steps, fluid, latest_force(fluid.parameters().body_force), membrane_velocities_lu_,
      friction_settings());
  last_friction_step_ = time_step;
  friction_applied_ = true;
}

std::span<const std::size_t> Cell::prepare_membrane_friction() {
  friction_.prepare(stencil_);
  return friction_.nodes();
}

void Cell::solve_membrane_friction_with(std::span<const double> density,
                                        std::span<const Vec3> momentum_lu,
                                        const std::array<double, 3>& body_force_lu,
                                        const LatticeFrame& frame, std::size_t time_step) {
  const auto dt_steps = static_cast<double>(time_step - last_friction_step_);
  friction_iterations_ = friction_.solve_with_moments(
      positions_lu_, membrane::EdgeNetwork::of(model_.topology()), friction_lu(frame), dt_steps,
      density, momentum_lu, latest_force(body_force_lu), membrane_velocities_lu_,
      friction_settings());
  last_friction_step_ = time_step;
  friction_applied_ = true;
}

void Cell::append_friction_solution(std::vector<double>& values) const {
  values.push_back(static_cast<double>(friction_iterations_));
  for (const Vec3& u : membrane_velocities_lu_) values.insert(values.end(), {u.x(), u.y(), u.z()});
  friction_.append_solution(values);
}

std::span<const double> Cell::adopt_friction_solution(std::span<const double> values,
                                                      std::size_t time_step) {
  const std::size_t count = 1 + 3 * membrane_velocities_lu_.size();
  if (values.size() < count) {
    throw std::invalid_argument("Cell::adopt_friction_solution: " + std::to_string(values.size()) +
                                " values for " + std::to_string(count));
  }
  friction_iterations_ = static_cast<std::size_t>(values[0]);
  for (std::size_t v = 0; v < membrane_velocities_lu_.size(); ++v) {
    membrane_velocities_lu_[v] = Vec3(values[1 + 3 * v], values[2 + 3 * v], values[3 + 3 * v]);
  }
  last_friction_step_ = time_step;
  friction_applied_ = true;
  return friction_.adopt_solution(values.subspan(count));
}

void Cell::add_membrane_friction(lattice::FluidSolver& fluid) const {
  if (friction_applied_) friction_.add_momentum_to(fluid);
}

void Cell::hold_volume() {
  if (!volume_hold_) volume_hold_.emplace(model_.triangles(), model_.topology());
}

void Cell::dilate(double factor) {
  const Vec3 centre = centroid_lu();
  for (Vec3& position : positions_lu_) position = centre + factor * (position - centre);
}

void Cell::set_reference(membrane::ReferenceState reference, const LatticeFrame& frame) {
  model_.set_reference(std::move(reference));
  workspace_ = model_.make_workspace();
  if (sub_spacing_drag_) use_sub_spacing_drag(drag_fluid_viscosity_sum_lu_, frame);
}

void Cell::use_sub_spacing_drag(double viscosity_sum_lu, const LatticeFrame& frame) {
  drag_fluid_viscosity_sum_lu_ = viscosity_sum_lu;
  sub_spacing_drag_.emplace(model_.triangles(), model_.topology());
  // The elastic forces at rest, in lattice units at lattice positions.
  membrane::MembraneWorkspace workspace = model_.make_workspace();
  membrane::MembraneForces forces = model_.make_forces();
  std::vector<Vec3> positions_um(vertex_count());
  const ForceFunction forces_at = [&](std::span<const Vec3> positions_lu, std::span<Vec3> out) {
    for (std::size_t v = 0; v < positions_lu.size(); ++v)
      positions_um[v] = frame.to_um(positions_lu[v]);
    model_.compute(positions_um, workspace, forces, membrane::ForceDetail::totals);
    for (std::size_t v = 0; v < out.size(); ++v) {
      out[v] = frame.lattice_force_per_pN * forces.total_pN[v];
    }
  };
  drag_rate_per_step_ =
      fastest_drag_rate(*sub_spacing_drag_, positions_lu_, forces_at, viscosity_sum_lu);
  drag_raised_by_ = std::max(1.0, drag_rate_per_step_ / kMaxDragRatePerStep);
  drag_viscosity_sum_lu_ = viscosity_sum_lu * drag_raised_by_;
}

void Cell::interpolate_and_advance(const ibm::GridView& grid,
                                   const lattice::VectorField& velocity) {
  ibm::interpolate_velocity(stencil_, grid, velocity[0].data(), velocity[1].data(),
                            velocity[2].data(), velocities_lu_);
  advance();
}

void Cell::advance_with(std::span<const Vec3> interpolated_velocities_lu) {
  if (interpolated_velocities_lu.size() != velocities_lu_.size()) {
    throw std::invalid_argument(
        "Cell::advance_with: " + std::to_string(interpolated_velocities_lu.size()) +
        " velocities for " + std::to_string(velocities_lu_.size()) + " vertices");
  }
  std::copy(interpolated_velocities_lu.begin(), interpolated_velocities_lu.end(),
            velocities_lu_.begin());
  advance();
}

void Cell::advance() {
  // After an implicit friction step the membrane moves as that step found it (the friction acted
  // on the fluid's state after streaming, which the latest collision's velocity precedes).
  if (friction_applied_) {
    std::copy(membrane_velocities_lu_.begin(), membrane_velocities_lu_.end(),
              velocities_lu_.begin());
    friction_applied_ = false;
  }
  // The forces are those of this step's start, where positions_lu_ still are.
  if (sub_spacing_drag_) {
    sub_spacing_drag_->add_velocities(positions_lu_, forces_lu_, drag_viscosity_sum_lu_,
                                      velocities_lu_);
  }
  if (volume_hold_) volume_hold_->apply(positions_lu_, velocities_lu_);
  previous_positions_lu_ = positions_lu_;
  advancer_.advance(positions_lu_, velocities_lu_);
}

void Cell::move_to(std::span<const Vec3> positions_um, const LatticeFrame& frame) {
  if (positions_um.size() != vertex_count()) {
    throw std::invalid_argument("coupling: " + std::to_string(positions_um.size()) +
                                " positions for a cell of " + std::to_string(vertex_count()) +
                                " vertices");
  }
  for (std::size_t v = 0; v < vertex_count(); ++v) {
    positions_lu_[v] = frame.to_lattice(positions_um[v]);
  }
  previous_positions_lu_ = positions_lu_;
  positions_um_.assign(positions_um.begin(), positions_um.end());
  std::fill(velocities_lu_.begin(), velocities_lu_.end(), Vec3::Zero());
  std::fill(membrane_velocities_lu_.begin(), membrane_velocities_lu_.end(), Vec3::Zero());
  advancer_.forget_history();
}

void Cell::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "positions_lu", positions_lu_);
  archive.put(prefix + "previous_positions_lu", previous_positions_lu_);
  archive.put(prefix + "velocities_lu", velocities_lu_);
  if (has_membrane_friction()) {
    archive.put(prefix + "membrane_velocities_lu", membrane_velocities_lu_);
    archive.put(prefix + "last_friction_step", {static_cast<double>(last_friction_step_)});
    friction_.save_state(archive, prefix);
  }
  advancer_.save_state(archive, prefix);
}

void Cell::restore_state(StateArchive& archive, const std::string& prefix,
                         const LatticeFrame& frame) {
  archive.take(prefix + "positions_lu", positions_lu_);
  archive.take(prefix + "previous_positions_lu", previous_positions_lu_);
  archive.take(prefix + "velocities_lu", velocities_lu_);
  if (has_membrane_friction()) {
    archive.take(prefix + "membrane_velocities_lu", membrane_velocities_lu_);
    last_friction_step_ =
        static_cast<std::size_t>(archive.take_number(prefix + "last_friction_step"));
    friction_.restore_state(archive, prefix);
  }
  advancer_.restore_state(archive, prefix, vertex_count());
  // Where the next step computes the forces; until then, what positions_um() shows.
  for (std::size_t v = 0; v < vertex_count(); ++v) positions_um_[v] = frame.to_um(positions_lu_[v]);
}

}  // namespace rbcsim::coupling
