#include "coupling/coupled_simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <exception>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "coupling/checkpoint.hpp"
#include "coupling/snapshot.hpp"
#include "io/state_archive_file.hpp"
#include "parallel/distributed_fluid.hpp"
#include "parallel/distributed_ibm.hpp"

namespace rbcsim::coupling {
namespace {

using Clock = std::chrono::steady_clock;

// Adds the seconds since `start` to `total` and restarts the clock.
void lap(Clock::time_point& start, double& total) {
  const auto now = Clock::now();
  total += std::chrono::duration<double>(now - start).count();
  start = now;
}

// The fluid is periodic along every axis (walls are nodes of the solid mask), except that the
// IBM must not reach across a Lees-Edwards plane, whose images slide: a cell touching it stops the
// run as having left the domain (many-cell runs will need the shifted images).
ibm::GridView grid_view_of(const lattice::FluidSolver& fluid) {
  const auto& grid = fluid.grid();
  const bool sliding_y = fluid.parameters().lees_edwards_velocity.has_value();
  return {grid.nx(), grid.ny(), grid.nz(), true, !sliding_y, true};
}

std::string cell_label(std::size_t cell) { return "cell " + std::to_string(cell); }

// Names of the checkpoint arrays of a cell and of a stop criterion.
std::string cell_prefix(std::size_t cell) { return cell_label(cell) + "."; }
std::string criterion_prefix(std::size_t index) {
  return "stop criterion " + std::to_string(index) + ".";
}

}  // namespace

double StepPhaseTimes::total_s() const {
  return membrane_s + contact_s + spread_s + indicator_s + fluid_s + friction_s + advance_s +
         checks_s + observers_s;
}

std::vector<std::pair<std::string, double>> ms_per_step_by_phase(const StepPhaseTimes& times) {
  const double ms_per_step = times.steps == 0 ? 0.0 : 1e3 / static_cast<double>(times.steps);
  return {{"membrane", times.membrane_s * ms_per_step},
          {"contact", times.contact_s * ms_per_step},
          {"spread", times.spread_s * ms_per_step},
          {"cytoplasm_indicator", times.indicator_s * ms_per_step},
          {"fluid", times.fluid_s * ms_per_step},
          {"membrane_friction", times.friction_s * ms_per_step},
          {"interpolate_advance", times.advance_s * ms_per_step},
          {"checks", times.checks_s * ms_per_step},
          {"observers", times.observers_s * ms_per_step}};
}

CoupledSimulation::CoupledSimulation(std::unique_ptr<lattice::FluidSolver> fluid,
                                     const units::UnitConverter& units,
                                     CouplingParameters parameters, const Vec3& origin_um)
    : fluid_(std::move(fluid)),
      units_(units),
      parameters_(std::move(parameters)),
      frame_{origin_um, units.to_physical(units::PhysicalUnit::length_um, 1.0),
             units.to_physical(units::PhysicalUnit::time_s, 1.0),
             units.to_lattice(units::PhysicalUnit::force_pN, 1.0)},
      grid_(grid_view_of(*fluid_)),
      kernel_(&ibm::find_delta_kernel(parameters_.kernel)),
      advance_scheme_(&ibm::find_point_advance_scheme(parameters_.point_advance)),
      lattice_force_per_pN_(units.to_lattice(units::PhysicalUnit::force_pN, 1.0)) {
  // The cytoplasm's indicator is smoothed over the reach of the kernel that couples the membrane.
  if (fluid_->has_viscosity_contrast()) {
    cytoplasm_.emplace(0.5 * kernel_->support_width, parameters_.cytoplasm_update_lu);
  }
  if (parameters_.processes.size() > 1) {
    parallel::require_within_ghost_planes(*kernel_);
    distributed_ = std::make_unique<parallel::DistributedFluid>(parameters_.processes, *fluid_,
                                                                parameters_.block_planes);
  }
}

CoupledSimulation::~CoupledSimulation() = default;
CoupledSimulation::CoupledSimulation(CoupledSimulation&&) noexcept = default;
CoupledSimulation& CoupledSimulation::operator=(CoupledSimulation&&) noexcept = default;

const lattice::FluidSolver& CoupledSimulation::fluid() const {
  if (distributed_ && fluid_gathered_step_ != time_step_) {
    throw std::logic_error(
        "CoupledSimulation::fluid(): across processes the fluid is gathered only for observers "
        "that declare reads_fluid, at the end of run() and for a failure dump");
  }
  return *fluid_;
}

bool CoupledSimulation::on_any_process(bool local) const {
  return distributed_ ? parameters_.processes.any(local) : local;
}

void CoupledSimulation::gather_fluid() {
  if (!distributed_ || fluid_gathered_step_ == time_step_) return;
  distributed_->copy_state_into(*fluid_);
  fluid_gathered_step_ = time_step_;
}

SubSpacingDragSummary CoupledSimulation::sub_spacing_drag_summary() const {
  SubSpacingDragSummary summary{.on = parameters_.sub_spacing_drag};
  for (const Cell& cell : cells_) {
    summary.fastest_rate_per_step =
        std::max(summary.fastest_rate_per_step, cell.sub_spacing_drag_rate());
    summary.viscosity_raised_by =
        std::max(summary.viscosity_raised_by, cell.sub_spacing_drag_raised_by());
    if (cell.sub_spacing_drag_raised_by() > 1.0) ++summary.raised_cells;
  }
  return summary;
}

std::size_t CoupledSimulation::add_cell(membrane::MembraneModel model,
                                        std::span<const Vec3> positions_um) {
  const std::size_t index = cells_.size();
  if (growth_stage_count(growth_) > 0) {
    // A growing cell starts at its first stage's reference; the model's own is its full size.
    full_references_.push_back(model.reference());
    model.set_reference(membrane::scaled_reference(
        model.reference(), growth_stage_scale(growth_, growth_stage(growth_, 0))));
  }
  Cell cell(std::move(model), positions_um, frame_, *advance_scheme_);
  if (parameters_.hold_volume) cell.hold_volume();
  if (parameters_.sub_spacing_drag) {
    // Lattice density 1: the dynamic viscosities are the kinematic ones, the cytoplasm's the
    // plasma's times the contrast.
    const lattice::FluidParameters& fluid = fluid_->parameters();
    cell.use_sub_spacing_drag(fluid_->viscosity() * (1.0 + fluid.inner_viscosity_ratio), frame_);
  }
  if (const auto problem =
          find_domain_exit(cell.positions_lu(), grid_, fluid_->solid_mask().data())) {
    throw InputError(cell_label(index),
                     *problem + " at the start: the cell does not fit the domain");
  }
  // Forces at the initial shape: the first snapshot shows them, and a shape already at a force
  // limit is refused here rather than at step 1.
  try {
    cell.compute_membrane_forces(frame_);
  } catch (const RuntimeFailure& failure) {
    throw InputError(cell_label(index), std::string("initial shape: ") + failure.what());
  }
  cells_.push_back(std::move(cell));
  force_cap_monitors_.emplace_back();
  return index;
}

void CoupledSimulation::grow_cells(const CellGrowth& growth) {
  require_valid(growth);
  if (time_step_ != 0 || !cells_.empty()) {
    throw std::invalid_argument("grow_cells: before the cells are added and the first step");
  }
  growth_ = growth;
  applied_growth_stage_ = growth_stage(growth_, 0);
}

double CoupledSimulation::cell_scale() const {
  return growth_stage_scale(growth_, growth_stage(growth_, time_step_));
}

void CoupledSimulation::apply_growth() {
  if (growth_stage_count(growth_) == 0) return;
  const std::size_t stage = growth_stage(growth_, time_step_);
  if (stage != applied_growth_stage_) {
    const bool grown = stage == growth_stage_count(growth_);
    const double scale = growth_stage_scale(growth_, stage);
    for_each_cell([&](std::size_t k) {
      cells_[k].set_reference(
          grown ? full_references_[k] : membrane::scaled_reference(full_references_[k], scale),
          frame_);
    });
    applied_growth_stage_ = stage;
  }
}

void CoupledSimulation::grow_cell_shapes() {
  if (growth_stage_count(growth_) == 0 || time_step_ >= growth_.steps) return;
  const double factor = growth_scale(growth_, time_step_ + 1) / growth_scale(growth_, time_step_);
  for_each_cell([this, factor](std::size_t k) { cells_[k].dilate(factor); });
}

void CoupledSimulation::add_observer(Observer observer) {
  if (observer.interval_steps == 0) {
    throw std::invalid_argument("observer '" + observer.name + "': interval of 0 steps");
  }
  if (std::ranges::any_of(observers_, [&](const RegisteredObserver& registered) {
        return registered.observer.name == observer.name;
      })) {
    throw std::invalid_argument("observer '" + observer.name + "' is already registered");
  }
  observers_.push_back({std::move(observer), std::nullopt});
}

void CoupledSimulation::add_external_force(ExternalForce force) {
  external_forces_.push_back(std::move(force));
}

void CoupledSimulation::set_cell_contact(const contact::ContactParameters& parameters,
                                         std::string_view option) {
  if (parameters.force_at_contact_pN != 0.0 && !(parameters.range_um > 0.0)) {
    throw InputError(std::string(option), "the contact range must be > 0");
  }
  contact_ = parameters;
  for (int axis = 0; axis < 3; ++axis) {
    const int nodes = axis == 0 ? grid_.nx : axis == 1 ? grid_.ny : grid_.nz;
    contact_box_.length_um[axis] = ibm::axis_periodic(grid_, axis) ? nodes * frame_.dx_um : 0.0;
  }
}

// Every cell's triangles in the numbering of contact_positions_um_ (cells one after the other),
// and each vertex's triangles: the surface law's input, fixed once the cells are added.
void CoupledSimulation::build_contact_surfaces() {
  contact_triangles_.clear();
  std::vector<std::vector<std::uint32_t>> of_vertex(contact_positions_um_.size());
  std::uint32_t offset = 0;
  for (const auto& cell : cells_) {
    for (const auto& triangle : cell.model().triangles()) {
      std::array<std::uint32_t, 3> global{};
      for (std::size_t c = 0; c < 3; ++c) {
        global[c] = offset + static_cast<std::uint32_t>(triangle[c]);
        of_vertex[global[c]].push_back(static_cast<std::uint32_t>(contact_triangles_.size()));
      }
      contact_triangles_.push_back(global);
    }
    offset += static_cast<std::uint32_t>(cell.vertex_count());
  }
  contact_vertex_triangle_offsets_.assign(1, 0);
  contact_vertex_triangles_.clear();
  for (const auto& triangles : of_vertex) {
    contact_vertex_triangles_.insert(contact_vertex_triangles_.end(), triangles.begin(),
                                     triangles.end());
    contact_vertex_triangle_offsets_.push_back(
        static_cast<std::uint32_t>(contact_vertex_triangles_.size()));
  }
}

void CoupledSimulation::add_contact_forces() {
  if (contact_.force_at_contact_pN == 0.0 || cells_.size() < 2) return;
  contact_positions_um_.clear();
  contact_owners_.clear();
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const auto positions = cells_[k].positions_um();
    contact_positions_um_.insert(contact_positions_um_.end(), positions.begin(), positions.end());
    contact_owners_.insert(contact_owners_.end(), positions.size(), static_cast<std::uint32_t>(k));
  }
  contact_forces_pN_.assign(contact_positions_um_.size(), Vec3::Zero());
  if (contact_.law == contact::ContactLaw::surface) {
    if (contact_vertex_triangle_offsets_.size() != contact_positions_um_.size() + 1) {
      build_contact_surfaces();
    }
    const contact::ContactSurfaces surfaces{contact_triangles_, contact_vertex_triangle_offsets_,
                                            contact_vertex_triangles_};
    // Across processes each searches for the vertices of the cells it computes (computes_cell).
    std::vector<char> owned(cells_.size(), 1);
    if (distributed_) {
      for (std::size_t k = 0; k < cells_.size(); ++k) owned[k] = computes_cell(k) ? 1 : 0;
    }
    const parallel::Communicator& processes = parameters_.processes;
    const contact::ContactSplit split{
        [&owned](std::uint32_t cell) { return owned[cell] != 0; },
        [&processes](std::span<const double> mine) { return processes.gather_to_all(mine); }};
    contact_statistics_ = contact::add_surface_contact_forces(
        contact_positions_um_, contact_owners_, surfaces, contact_, contact_box_,
        contact_forces_pN_, contact_workspace_, distributed_ ? &split : nullptr);
  } else {
    contact_statistics_ =
        contact::add_cell_contact_forces(contact_positions_um_, contact_owners_, contact_,
                                         contact_box_, contact_forces_pN_, contact_workspace_);
  }
  if (contact_statistics_.close_pairs > 0) ++close_contact_steps_;
  if (contact_statistics_.capped_pushes > 0) ++capped_contact_steps_;
  std::size_t offset = 0;
  for (auto& cell : cells_) {
    auto forces = cell.external_forces_pN();
    for (std::size_t v = 0; v < forces.size(); ++v) forces[v] += contact_forces_pN_[offset + v];
    offset += forces.size();
  }
}

void CoupledSimulation::add_stop_criterion(std::unique_ptr<StopCriterion> criterion) {
  stop_criteria_.push_back(std::move(criterion));
}

double CoupledSimulation::time_s() const {
  return units_.to_physical(units::PhysicalUnit::time_s, static_cast<double>(time_step_));
}

std::vector<Vec3> CoupledSimulation::positions_now_um(std::size_t cell_index) const {
  const auto positions_lu = cell(cell_index).positions_lu();
  std::vector<Vec3> positions_um;
  positions_um.reserve(positions_lu.size());
  for (const Vec3& position_lu : positions_lu) positions_um.push_back(frame_.to_um(position_lu));
  return positions_um;
}

void CoupledSimulation::move_cell(std::size_t cell_index, std::span<const Vec3> positions_um) {
  cells_.at(cell_index).move_to(positions_um, frame_);
}

std::vector<std::size_t> CoupledSimulation::capped_steps_per_cell() const {
  std::vector<std::size_t> steps;
  for (const auto& monitor : force_cap_monitors_) steps.push_back(monitor.steps_with_capping());
  return steps;
}

template <class Body>
std::vector<std::exception_ptr> CoupledSimulation::run_on_cells(
    std::span<const std::size_t> indices, const Body& body) {
  const auto count = static_cast<std::ptrdiff_t>(indices.size());
  std::vector<std::exception_ptr> failures(indices.size());
  const auto run_cell = [&body, &failures, indices](std::ptrdiff_t i) {
    try {
      body(indices[static_cast<std::size_t>(i)]);
    } catch (...) {
      failures[static_cast<std::size_t>(i)] = std::current_exception();
    }
  };
  // Several cells: one region over the cells, whose kernels then run on one thread each (their
  // results do not depend on the thread count). One cell: no region here, so that its kernels'
  // own regions are top-level ones. Inside even an inactive region (`if (false)`) they would be
  // nested, and GNU OpenMP starts threads for every nested team, which then compete for the
  // cores with the top-level team's spinning workers: a two-thread capillary step 5x slower than
  // a one-thread one (docs/performance.md).
  if (count == 1) {
    run_cell(0);
  } else {
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t i = 0; i < count; ++i) run_cell(i);
  }
  return failures;
}

template <class Body>
void CoupledSimulation::for_each_cell(const Body& body) {
  std::vector<std::size_t> all(cells_.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  fail_on_first(run_on_cells(all, body));
}

void CoupledSimulation::fail_on_first(std::span<const std::exception_ptr> failures_by_cell) {
  for (std::size_t k = 0; k < failures_by_cell.size(); ++k) {
    if (!failures_by_cell[k]) continue;
    try {
      std::rethrow_exception(failures_by_cell[k]);
    } catch (const RuntimeFailure& failure) {
      fail(k, failure.what());
    }
  }
}

void CoupledSimulation::compute_cell_forces() {
  if (distributed_ && cells_.size() > 1 && compute_owned_cell_forces()) return;
  // One process, one cell, or a failure somewhere: every cell here, so that a failure stops every
  // process alike (the lowest-indexed failing cell, for_each_cell).
  for_each_cell([this](std::size_t k) {
    cells_[k].compute_membrane_forces(frame_);
    for (const auto& force : external_forces_) force(k, cells_[k], cells_[k].external_forces_pN());
  });
}

template <class Append, class Adopt>
void CoupledSimulation::share_computed_cells(std::span<const std::size_t> computed,
                                             std::size_t expected, const char* what,
                                             const Append& append, const Adopt& adopt) {
  std::vector<double> mine;
  for (const std::size_t k : computed) {
    mine.push_back(static_cast<double>(k));
    append(k, mine);
  }
  const std::vector<double> all = parameters_.processes.gather_to_all(mine);
  std::span<const double> rest(all);
  std::size_t adopted = 0;
  while (!rest.empty()) {
    const auto k = static_cast<std::size_t>(rest.front());
    if (k >= cells_.size())
      throw std::logic_error("CoupledSimulation: a copy of no cell came back");
    rest = adopt(k, rest.subspan(1));
    ++adopted;
  }
  if (adopted != expected) {
    throw std::logic_error("CoupledSimulation: the " + std::string(what) + " of " +
                           std::to_string(adopted) + " of " + std::to_string(expected) +
                           " cells came back");
  }
}

bool CoupledSimulation::owns_cell(std::size_t index) const {
  if (!distributed_) return true;
  const int nz = distributed_->global_grid().nz();
  const int plane = lattice::LatticeGrid::wrap(
      static_cast<int>(std::floor(cells_.at(index).centroid_lu().z())), nz);
  return plane >= distributed_->z_begin() && plane < distributed_->z_end();
}

bool CoupledSimulation::computes_cell(std::size_t index) const {
  if (!distributed_) return true;
  if (computed_here_.size() != cells_.size()) {  // cells were added: deal them out again
    // Cell k goes to the process whose share [r V / P, (r + 1) V / P) of the V vertices holds
    // the cell's first vertex (cells in index order): the same deal on every process.
    std::size_t total = 0;
    for (const Cell& cell : cells_) total += cell.vertex_count();
    const auto processes = static_cast<std::size_t>(parameters_.processes.size());
    const auto rank = static_cast<std::size_t>(parameters_.processes.rank());
    computed_here_.assign(cells_.size(), 0);
    std::size_t first_vertex = 0;
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      computed_here_[k] =
          first_vertex * processes >= rank * total && first_vertex * processes < (rank + 1) * total;
      first_vertex += cells_[k].vertex_count();
    }
  }
  return computed_here_.at(index) != 0;
}

// The same code on the same positions gives the same forces on any process: the copies are the
// values the computing process found, bit for bit, and the step goes on as if every process had
// computed every cell.
bool CoupledSimulation::compute_owned_cell_forces() {
  std::vector<std::size_t> owned;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    if (computes_cell(k)) owned.push_back(k);
  }
  const auto failures = run_on_cells(owned, [this](std::size_t k) {
    cells_[k].compute_membrane_forces(frame_);
    for (const auto& force : external_forces_) force(k, cells_[k], cells_[k].external_forces_pN());
  });
  bool failed = false;
  for (const auto& failure : failures) {
    if (!failure) continue;
    try {
      std::rethrow_exception(failure);
    } catch (const RuntimeFailure&) {
      failed = true;  // any other exception goes on up: a bug, which stops the run
    }
  }
  const parallel::Communicator& processes = parameters_.processes;
  if (processes.any(failed)) return false;
  share_computed_cells(
      owned, cells_.size(), "forces",
      [this](std::size_t k, std::vector<double>& values) { cells_[k].append_forces(values); },
      [this](std::size_t k, std::span<const double> values) {
        return cells_[k].adopt_forces(values, frame_);
      });
  return true;
}

void CoupledSimulation::spread_forces() {
  auto start = Clock::now();
  apply_growth();
  compute_cell_forces();
  lap(start, phase_times_.membrane_s);
  add_contact_forces();
  lap(start, phase_times_.contact_s);
  const std::uint8_t* solid_mask = fluid_->solid_mask().data();
  for_each_cell([this, solid_mask](std::size_t k) {
    cells_[k].prepare_spread(lattice_force_per_pN_, *kernel_, grid_, solid_mask);
  });
  spread_sources_.clear();
  for (const Cell& cell : cells_) spread_sources_.push_back(cell.spread_source());
  if (distributed_) {
    parallel::spread_onto_slab(spread_sources_, *distributed_);
  } else {
    auto& force_density = fluid_->force_density();
    ibm::spread_forces(spread_sources_, grid_, force_density[0].data(), force_density[1].data(),
                       force_density[2].data());
  }
  lap(start, phase_times_.spread_s);
  forces_spread_ = true;
}

void CoupledSimulation::advance_fluid() {
  if (distributed_) {
    distributed_->step();
  } else {
    fluid_->step();
  }
  if ((time_step_ + 1) % parameters_.stability.fluid_check_interval_steps == 0) {
    try {
      if (distributed_) {
        distributed_->require_finite_velocity();  // on every process
      } else {
        fluid_->require_finite_velocity();
      }
    } catch (const RuntimeFailure& failure) {
      fail(std::nullopt, failure.what());
    }
  }
}

// Every cell solves on the same fluid state, in parallel, then their momenta are added in cell
// order: independent of the thread count. Cells whose stencils share nodes meet each other's
// friction a step later than in a solve of all cells together, as their forces meet (first order
// in the step, like the explicit coupling itself).
void CoupledSimulation::apply_membrane_friction() {
  if (distributed_) {
    apply_distributed_membrane_friction();
    return;
  }
  const lattice::FluidSolver& fluid = *fluid_;
  if (!fluid.populations_natural()) return;  // Cell::solve_membrane_friction
  for_each_cell([this, &fluid](std::size_t k) {
    cells_[k].solve_membrane_friction(fluid, frame_, time_step_ + 1);
  });
  for (const Cell& cell : cells_) cell.add_membrane_friction(*fluid_);
  count_friction_iterations();
}

void CoupledSimulation::count_friction_iterations() {
  for (const Cell& cell : cells_) {
    if (!cell.has_membrane_friction()) continue;
    ++phase_times_.friction_solves;
    phase_times_.friction_iterations += cell.friction_iterations();
  }
}

// Across processes every process holds every cell, but the nodes under a cell lie on several of
// them. Each process supplies the pre-collision moments of its own nodes under every cell
// (copies, no sums), the process that computes a cell (computes_cell) solves it, and the copies
// of the cell elsewhere adopt that solve; every process then adds every cell's momentum at its own
// nodes, cell after cell, as apply_membrane_friction adds them on the undivided solver. So the
// cells, their warm starts and the fluid stay those of one process, bit for bit. If a solve fails
// anywhere, every process also solves the cells it does not compute, so that all stop on the same
// lowest failing cell.
void CoupledSimulation::apply_distributed_membrane_friction() {
  if (!distributed_->populations_natural()) return;  // the same step on every process
  std::vector<std::size_t> with_friction;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    if (cells_[k].has_membrane_friction()) with_friction.push_back(k);
  }
  if (with_friction.empty()) return;
  constexpr std::size_t kValuesPerNode = 6;  // append_own_pre_collision_moments
  std::vector<std::span<const std::size_t>> nodes(cells_.size());
  std::vector<double> own_moments;
  for (const std::size_t k : with_friction) {
    nodes[k] = cells_[k].prepare_membrane_friction();
    distributed_->append_own_pre_collision_moments(nodes[k], static_cast<double>(k), own_moments);
  }
  const parallel::Communicator& processes = parameters_.processes;
  const std::vector<double> moments = processes.gather_to_all(own_moments);
  std::vector<std::vector<double>> density(cells_.size());
  std::vector<std::vector<Vec3>> momentum(cells_.size());
  std::size_t expected = 0;
  for (const std::size_t k : with_friction) {
    density[k].assign(nodes[k].size(), 0.0);
    momentum[k].assign(nodes[k].size(), Vec3::Zero());
    expected += nodes[k].size();
  }
  if (moments.size() != kValuesPerNode * expected) {  // the same on every process
    throw std::logic_error("CoupledSimulation: the moments of " +
                           std::to_string(moments.size() / kValuesPerNode) + " of " +
                           std::to_string(expected) + " nodes under the membranes came back");
  }
  for (std::size_t i = 0; i < moments.size(); i += kValuesPerNode) {
    const auto k = static_cast<std::size_t>(moments[i]);
    const auto n = static_cast<std::size_t>(moments[i + 1]);
    density[k].at(n) = moments[i + 2];
    momentum[k].at(n) = Vec3(moments[i + 3], moments[i + 4], moments[i + 5]);
  }
  const std::size_t step = time_step_ + 1;
  const auto& body_force = distributed_->local().parameters().body_force;
  const auto solve = [&](std::size_t k) {
    cells_[k].solve_membrane_friction_with(density[k], momentum[k], body_force, frame_, step);
  };
  std::vector<std::size_t> owned;
  std::vector<std::size_t> copies;
  for (const std::size_t k : with_friction) (computes_cell(k) ? owned : copies).push_back(k);
  std::vector<std::exception_ptr> failures(cells_.size());
  const auto record = [&failures](std::span<const std::size_t> indices,
                                  const std::vector<std::exception_ptr>& found) {
    bool any = false;
    for (std::size_t i = 0; i < indices.size(); ++i) {
      failures[indices[i]] = found[i];
      any = any || found[i] != nullptr;
    }
    return any;
  };
  const bool failed_here = record(owned, run_on_cells(owned, solve));
  if (processes.any(failed_here)) {
    record(copies, run_on_cells(copies, solve));
    fail_on_first(failures);
  }
  // The solving process adopts its own solve too: the same values.
  share_computed_cells(
      owned, with_friction.size(), "friction",
      [this](std::size_t k, std::vector<double>& values) {
        cells_[k].append_friction_solution(values);
      },
      [this, step](std::size_t k, std::span<const double> values) {
        return cells_[k].adopt_friction_solution(values, step);
      });
  for (const std::size_t k : with_friction) {
    distributed_->add_momentum_on_own_nodes(nodes[k], cells_[k].membrane_friction_momentum());
  }
  count_friction_iterations();
}

void CoupledSimulation::advance_cells() {
  if (distributed_) {
    std::vector<parallel::InterpolationSource> sources;
    for (const Cell& cell : cells_) sources.push_back({&cell.stencil(), cell.positions_lu()});
    std::vector<std::vector<Vec3>> velocities;
    try {
      velocities = parallel::interpolate_on_slabs(sources, *kernel_, *distributed_);
    } catch (const RuntimeFailure& failure) {
      fail(std::nullopt, failure.what());
    }
    for_each_cell([this, &velocities](std::size_t k) { cells_[k].advance_with(velocities[k]); });
    return;
  }
  for_each_cell(
      [this](std::size_t k) { cells_[k].interpolate_and_advance(grid_, fluid_->velocity()); });
}

void CoupledSimulation::check_cells() {
  const auto& limits = parameters_.stability;
  for_each_cell([this, &limits](std::size_t k) {
    const Cell& cell = cells_[k];
    auto problem = find_vertex_motion_problem(cell.previous_positions_lu(), cell.positions_lu(),
                                              cell.velocities_lu(), limits.max_vertex_step_lu);
    if (!problem)
      problem = find_domain_exit(cell.positions_lu(), grid_, fluid_->solid_mask().data());
    if (!problem) {
      problem = force_cap_monitors_[k].record(
          cell.membrane_forces().capped_vertex_count, cell.vertex_count(),
          cell.model().parameters().vertex_force_cap_pN, limits);
    }
    if (problem) throw RuntimeFailure(*problem);
  });
}

void CoupledSimulation::step() {
  if (!forces_spread_) spread_forces();
  auto start = Clock::now();
  if (cytoplasm_) {
    // Across processes every process locates every cell's cytoplasm on its copy of the whole
    // lattice's classes, and its slab takes its planes of them.
    if (cytoplasm_->update(cells_, grid_, fluid_->viscosity_classes()) && distributed_) {
      distributed_->set_viscosity_classes(fluid_->viscosity_classes());
    }
    lap(start, phase_times_.indicator_s);
  }
  advance_fluid();
  lap(start, phase_times_.fluid_s);
  apply_membrane_friction();
  lap(start, phase_times_.friction_s);
  advance_cells();
  grow_cell_shapes();
  lap(start, phase_times_.advance_s);
  check_cells();
  lap(start, phase_times_.checks_s);
  forces_spread_ = false;
  ++time_step_;
  ++phase_times_.steps;
  apply_growth();  // between steps the references are those of the next step (cell_scale())
  notify_due_observers();
  lap(start, phase_times_.observers_s);
}

void CoupledSimulation::notify(RegisteredObserver& registered) {
  if (registered.observer.needs_term_forces) add_term_forces();
  if (registered.observer.reads_fluid) gather_fluid();
  registered.observer.observe(*this);
  registered.last_observed_step = time_step_;
}

void CoupledSimulation::notify_due_observers() {
  for (auto& registered : observers_) {
    if (time_step_ % registered.observer.interval_steps == 0) notify(registered);
  }
}

void CoupledSimulation::observe_all() {
  for (auto& registered : observers_) notify(registered);
}

std::optional<std::string> CoupledSimulation::stop_reason() {
  for (auto& criterion : stop_criteria_) {
    if (auto reason = criterion->check(*this)) return reason;
  }
  return std::nullopt;
}

RunSummary CoupledSimulation::run() {
  if (stop_criteria_.empty()) {
    throw std::logic_error("CoupledSimulation::run needs at least one stop criterion");
  }
  if (time_step_ == 0) observe_all();
  RunSummary summary;
  std::optional<std::string> reason;
  auto last_checkpoint = Clock::now();
  while (!reason) {
    if (on_any_process(interrupt_requested())) {
      // A signal may reach some processes only (kill -INT to one): all stop alike.
      if (!interrupt_requested()) request_interrupt(SIGINT);
      stop_interrupted();
    }
    step();
    ++summary.steps;
    reason = stop_reason();
    if (!reason) checkpoint_if_due(last_checkpoint);
  }
  gather_fluid();
  notify_observers_of_final_state();
  summary.time_s = time_s();
  summary.stop_reason = *reason;
  summary.capped_steps_per_cell = capped_steps_per_cell();
  return summary;
}

void CoupledSimulation::notify_observers_of_final_state() {
  for (auto& registered : observers_) {
    if (registered.last_observed_step != time_step_) notify(registered);
  }
}

void CoupledSimulation::stop_interrupted() {
  gather_fluid();
  notify_observers_of_final_state();
  write_checkpoint_now();
  throw_if_interrupted();
  throw std::logic_error("stop_interrupted without an interrupt");
}

void CoupledSimulation::checkpoint_if_due(Clock::time_point& last_checkpoint) const {
  const auto& policy = checkpoint_policy_;
  if (policy.file.empty()) return;
  const bool steps_due = policy.every_steps > 0 && time_step_ % policy.every_steps == 0;
  // Across processes every clock has its say: all write (collectively) when any is due.
  const bool time_due =
      policy.every_wall_s > 0.0 &&
      on_any_process(std::chrono::duration<double>(Clock::now() - last_checkpoint).count() >=
                     policy.every_wall_s);
  if (!steps_due && !time_due) return;
  write_checkpoint_now();
  last_checkpoint = Clock::now();
}

void CoupledSimulation::write_checkpoint_now() const {
  if (!checkpoint_policy_.file.empty()) {
    write_checkpoint(checkpoint_policy_.file, *this, checkpoint_policy_.config_fingerprint);
  }
}

void CoupledSimulation::resume_from(const std::filesystem::path& checkpoint_file) {
  if (!distributed_) {
    read_checkpoint(checkpoint_file, *this, checkpoint_policy_.config_fingerprint);
    return;
  }
  // Every process reads the file; they agree before the collective restore, so that one that
  // cannot read it stops them all with the reason (rank 0's, if it is among them).
  StateArchive archive;
  std::string problem;
  try {
    archive = io::read_state_archive(checkpoint_file, kCheckpointVersion,
                                     checkpoint_policy_.config_fingerprint);
  } catch (const InputError& error) {
    problem = error.what();
  }
  if (on_any_process(!problem.empty())) {
    if (!problem.empty()) throw InputError(problem);
    throw InputError(checkpoint_file.string(), "unreadable on another process of the run");
  }
  restore_state(archive);
  archive.require_all_taken();
}

void CoupledSimulation::save_state(StateArchive& archive) const {
  if (forces_spread_) throw std::logic_error("save_state between spread_forces() and step()");
  archive.put("simulation.time_step", {static_cast<double>(time_step_)});
  archive.put("simulation.close_contact_steps", {static_cast<double>(close_contact_steps_)});
  archive.put("simulation.capped_contact_steps", {static_cast<double>(capped_contact_steps_)});
  if (distributed_) {
    distributed_->save_state(archive);  // the undivided solver's arrays, on rank 0
  } else {
    fluid_->save_state(archive);
  }
  if (cytoplasm_) cytoplasm_->save_state(archive);
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    cells_[k].save_state(archive, cell_prefix(k));
    force_cap_monitors_[k].save_state(archive, cell_prefix(k));
  }
  for (std::size_t i = 0; i < stop_criteria_.size(); ++i) {
    stop_criteria_[i]->save_state(archive, criterion_prefix(i));
  }
}

void CoupledSimulation::restore_state(StateArchive& archive) {
  time_step_ = static_cast<std::size_t>(archive.take_number("simulation.time_step"));
  close_contact_steps_ =
      static_cast<std::size_t>(archive.take_number("simulation.close_contact_steps"));
  capped_contact_steps_ =
      static_cast<std::size_t>(archive.take_number("simulation.capped_contact_steps"));
  if (distributed_) {
    distributed_->restore_state(archive);  // from rank 0's archive
    if (!parameters_.processes.is_root()) {
      // The others read the same file: its fluid arrays are taken, not left over.
      StateArchive shape("the undivided fluid");
      fluid_->save_state(shape);
      for (const auto& entry : shape.arrays()) archive.take(entry.first, std::nullopt);
    }
    fluid_gathered_step_.reset();
  } else {
    fluid_->restore_state(archive);
  }
  if (cytoplasm_) cytoplasm_->restore_state(archive, cells_);
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    cells_[k].restore_state(archive, cell_prefix(k), frame_);
    force_cap_monitors_[k].restore_state(archive, cell_prefix(k));
  }
  for (std::size_t i = 0; i < stop_criteria_.size(); ++i) {
    stop_criteria_[i]->restore_state(archive, criterion_prefix(i));
  }
  forces_spread_ = false;
  applied_growth_stage_.reset();  // the stage of the restored step, set at the next
  // The state restored was observed by the run that saved it.
  for (auto& registered : observers_) {
    registered.last_observed_step = time_step_;
    if (registered.observer.resumed) registered.observer.resumed(*this);
  }
}

void CoupledSimulation::add_term_forces() {
  for (auto& cell : cells_) cell.add_term_forces(frame_);
}

void CoupledSimulation::fail(std::optional<std::size_t> cell, const std::string& reason) {
  std::string where = "step " + std::to_string(time_step_ + 1) + ", " +
                      (cell ? cell_label(*cell) : std::string("fluid")) + ": " + reason;
  if (parameters_.run_directory.empty()) {
    throw RuntimeFailure(where + "; no dump (no run directory)");
  }
  const auto directory = parameters_.run_directory / "failure";
  try {
    // The dump shows each term's forces of the failing step where they can be computed (a term
    // at its limit cannot: then the dump has the totals of the step before).
    try {
      add_term_forces();
    } catch (const RuntimeFailure&) {
    }
    gather_fluid();
    write_failure_dump(directory, *this, cell, reason);
  } catch (const std::exception& dump_error) {
    throw RuntimeFailure(where + "; the dump to " + directory.string() +
                         " failed: " + dump_error.what());
  }
  throw RuntimeFailure(where + "; dump written to " + directory.string());
}

}  // namespace rbcsim::coupling
