// The coupled lattice Boltzmann - immersed boundary - membrane time loop (docs/architecture.md) for
// a list of cells (one now, many later). One step:
//   1. membrane forces at the current vertex positions, plus the external-force hooks (tweezers,
//      walls) and, with several cells, their contact (contact/cell_repulsion.hpp);
//   2. pN -> lattice force, one interpolation stencil per cell, spread onto the force density
//      (the sum of the spread forces equals the sum of the vertex forces);
//   3. fluid collide-and-stream with that force (Guo); with a viscosity contrast
//      (`physics.cytoplasm_viscosity_ratio`), the cells' interiors are located first, from the
//      positions of this step or, if no vertex has moved far since, of an earlier one
//      (cytoplasm_indicator.hpp); with membrane viscosity, then the implicit friction step on
//      the fluid under each membrane (membrane_friction.hpp), when the populations are natural;
//   4. the Guo-corrected velocity interpolated at the vertices with the same stencil (after a
//      friction step: the membrane velocity that step found);
//   5. vertices advanced (forward Euler by default, `ibm.point_advance`), with `ibm.hold_volume`
//      less the velocity that would change the cell's enclosed volume (volume_hold.hpp);
//   6. stability checks (stability.hpp), then the observers that are due.
// Every phase is deterministic, so results do not depend on the number of OpenMP threads.
//
// Across processes (CouplingParameters::processes, more than one): the fluid runs on the
// distributed lattice (parallel/distributed_fluid.hpp), cut from the undivided solver the case set
// up; every process holds every cell, and the cells are dealt out among the processes by vertex
// count (computes_cell). With several cells, each cell's membrane and hook forces and its surface
// contact search are computed by its process and copied to all; each process spreads the forces
// onto its own planes and interpolates the vertices in its planes, and the velocities are copied
// to all (parallel/distributed_ibm.hpp); with membrane viscosity, a cell's process solves its
// friction step from the moments every process supplies for its own nodes, and every process adds
// the momentum at its own nodes; with a viscosity contrast, every process locates every cytoplasm
// and its slab takes its planes of the classes. The state is bit-identical to one process's, on
// any number of processes. Observers and stop criteria run on
// every process alike; only rank 0 writes files.
//
// An instability stops the run (docs/physics.md, "Failures"): if a run directory is set, a dump
// (membrane .vtp of every cell, fluid .vti, failure.json) is written to <run directory>/failure/,
// then RuntimeFailure("step N, cell K: reason; dump written to DIR") is thrown (exit code 1).
#pragma once

#include <chrono>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/state_archive.hpp"
#include "contact/cell_list.hpp"
#include "contact/cell_repulsion.hpp"
#include "contact/surface_repulsion.hpp"
#include "coupling/cell.hpp"
#include "coupling/cell_growth.hpp"
#include "coupling/cytoplasm_indicator.hpp"
#include "coupling/stability.hpp"
#include "coupling/stop_criteria.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"
#include "ibm/point_advance.hpp"
#include "lattice/fluid_solver.hpp"
#include "parallel/communicator.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::parallel {
class DistributedFluid;
}

namespace rbcsim::coupling {

struct CouplingParameters {
  std::string kernel = "phi2";          // ibm.kernel: a name of ibm::delta_kernels()
  std::string point_advance = "euler";  // ibm.point_advance: a name of ibm::point_advance_schemes()
  // ibm.cytoplasm_update_dx: with a viscosity contrast, the cytoplasm's indicator is recomputed
  // once a vertex has moved this far (lattice spacings) since the last time; 0: every step.
  double cytoplasm_update_lu = 0.05;
  // ibm.hold_volume: every cell's vertices move so as to keep its enclosed volume
  // (volume_hold.hpp).
  bool hold_volume = false;
  // ibm.sub_spacing_drag: every cell's vertices also move with the fluid's drag on the
  // membrane's modes finer than the lattice (sub_spacing_drag.hpp).
  bool sub_spacing_drag = false;
  StabilityLimits stability;
  // Where failure dumps go (and what observers may write to); empty: no dump.
  std::filesystem::path run_directory;
  // The processes the fluid is cut across: one (the default) steps the undivided solver, several
  // its slabs.
  parallel::Communicator processes = parallel::Communicator::self();
  // lattice.block_planes: the z-planes of one block of the decomposition (at least 2).
  int block_planes = 4;
};

// When run() writes a checkpoint (checkpoint.hpp) to `file`: every `every_steps` steps, every
// `every_wall_s` seconds of wall-clock time (whichever comes first; 0 = not by that measure), and
// when interrupted. An empty file: never.
struct CheckpointPolicy {
  std::filesystem::path file;
  std::string config_fingerprint;  // of the run's resolved config; a resume must match it
  std::size_t every_steps = 0;
  double every_wall_s = 0.0;
};

class CoupledSimulation;

// Called every `interval_steps` steps, after the step's checks, with the simulation to read.
struct Observer {
  std::string name;  // unique within a simulation
  std::size_t interval_steps = 1;
  std::function<void(const CoupledSimulation&)> observe;
  // Optional: called once a checkpoint is restored, so an observer that writes a growing file
  // (a snapshot collection) continues what the interrupted run wrote up to that state.
  std::function<void(const CoupledSimulation&)> resumed = nullptr;
  // Whether it reads each membrane term's forces (Cell::membrane_forces().terms): a step computes
  // only the totals it spreads, and the per-term forces of that step are added before such an
  // observer is called.
  bool needs_term_forces = false;
  // Whether it reads fluid(): across processes, the fluid is then gathered before it is called.
  bool reads_fluid = false;
};

// Adds forces (pN) to a cell's vertices every step, e.g. optical tweezers. Called after the
// membrane forces, with the cell's positions_um() current; with several cells, for different cells
// at once on different threads, so it may write only `forces_pN`.
using ExternalForce =
    std::function<void(std::size_t cell_index, const Cell& cell, std::span<Vec3> forces_pN)>;

// Wall-clock seconds spent in each phase since construction or the last reset.
struct StepPhaseTimes {
  double membrane_s = 0.0;   // phase 1 (membrane and external forces)
  double contact_s = 0.0;    // phase 1, the contact between cells (several cells only)
  double spread_s = 0.0;     // phase 2 (stencils, spreading)
  double indicator_s = 0.0;  // phase 3, locating the cytoplasm (viscosity contrast only)
  double fluid_s = 0.0;      // phase 3
  double friction_s = 0.0;   // phase 3, the implicit membrane friction (membrane viscosity only)
  double advance_s = 0.0;    // phases 4-5 (interpolation, vertex advance)
  double checks_s = 0.0;     // phase 6, the stability checks
  double observers_s = 0.0;  // observers (output, measurements)
  std::size_t steps = 0;
  // The implicit friction's solves (one per cell with membrane viscosity every second step with
  // the AA kernel) and their conjugate-gradient iterations: what the friction phase's time is made
  // of.
  std::size_t friction_solves = 0;
  std::size_t friction_iterations = 0;

  double total_s() const;
};

// Each phase's name ("membrane", "contact", "spread", "cytoplasm_indicator", "fluid",
// "membrane_friction", "interpolate_advance", "checks", "observers") and its ms per step, in the
// step's order: where a run's time goes (rbcsim bench, result.json). Zeros before any step.
std::vector<std::pair<std::string, double>> ms_per_step_by_phase(const StepPhaseTimes& times);

struct RunSummary {
  std::size_t steps = 0;  // taken by this run() call
  double time_s = 0.0;    // physical time of the simulation when it stopped
  std::string stop_reason;
  // Per cell: steps in which the membrane's force cap clamped at least one vertex.
  std::vector<std::size_t> capped_steps_per_cell;
};

class CoupledSimulation {
 public:
  // The fluid's geometry (walls, inlets) must be set before; the simulation owns it from here.
  // `units` converts forces and fixes dx; `origin_um` is where lattice node (0, 0, 0) sits.
  // Throws InputError for an unknown kernel or point-advance scheme.
  // Across processes (parameters.processes), every process passes the same fluid; InputError
  // for what does not run there yet.
  CoupledSimulation(std::unique_ptr<lattice::FluidSolver> fluid, const units::UnitConverter& units,
                    CouplingParameters parameters, const Vec3& origin_um = Vec3::Zero());
  ~CoupledSimulation();
  CoupledSimulation(CoupledSimulation&&) noexcept;
  CoupledSimulation& operator=(CoupledSimulation&&) noexcept;

  // Adds a cell whose vertices start at positions_um (one per vertex of the model); returns its
  // index. Throws InputError naming the cell if a vertex lies outside the domain or in a wall.
  std::size_t add_cell(membrane::MembraneModel model, std::span<const Vec3> positions_um);
  // The cells added from now on start at growth.start_scale of their stress-free size and grow
  // to it over the first growth.steps steps (cell_growth.hpp): add_cell scales each one's
  // reference (the model's is its full size), which rises in stages at the start of the steps
  // and is the model's own again once grown; while they grow, each step scales every cell's
  // vertices about its centroid by the growth of the step (Cell::dilate), after the flow moved
  // them, so that their shape keeps pace with the reference. Place the cells at their start size.
  // Throws
  // std::invalid_argument for an invalid growth, or when cells were added or steps taken before.
  void grow_cells(const CellGrowth& growth);
  // The scale of the cells' reference during the next step (1 without growth).
  double cell_scale() const;
  // Throws std::invalid_argument for a duplicate name or an interval of 0.
  void add_observer(Observer observer);
  void add_external_force(ExternalForce force);
  // Contact between cells from the next step on, added to their external forces after the hooks.
  // Pairs are found across the lattice's periodic axes (minimum image). Throws InputError naming
  // `option` for a non-positive range with a non-zero force.
  void set_cell_contact(const contact::ContactParameters& parameters, std::string_view option);
  // What the latest step's contact found; in how many steps so far two cells came within a
  // quarter of the range (ContactStatistics::close_pairs > 0), and in how many a push was held
  // at the contact's force cap (ContactStatistics::capped_pushes > 0).
  const contact::ContactStatistics& contact_statistics() const { return contact_statistics_; }
  std::size_t close_contact_steps() const { return close_contact_steps_; }
  std::size_t capped_contact_steps() const { return capped_contact_steps_; }
  void add_stop_criterion(std::unique_ptr<StopCriterion> criterion);

  // One coupled step (phases 1-6).
  void step();
  // Phases 1-2 alone: the forces of this step spread onto the fluid's force density, which the
  // next step() then uses instead of spreading again. For tests and diagnostics.
  void spread_forces();
  // Steps until a stop criterion holds (std::logic_error if there is none). Observers see the
  // initial state (when no step was taken yet) and the final state. Checks the interrupt flag
  // (common/interrupt.hpp) before every step: when set, the observers see the state reached, a
  // checkpoint is written (if a policy is set) and Interrupted is thrown.
  RunSummary run();
  // Checkpoints written by run() from now on.
  void set_checkpoint_policy(CheckpointPolicy policy) { checkpoint_policy_ = std::move(policy); }
  // Writes a checkpoint now, if the policy names a file.
  void write_checkpoint_now() const;
  // Continues from a checkpoint written by a simulation built the same way (read_checkpoint).
  void resume_from(const std::filesystem::path& checkpoint_file);

  // The complete state between two steps (checkpoint.hpp): step count, fluid, cells with their
  // point-advance history, force-cap monitors, stop criteria. restore_state throws InputError
  // naming the archive for arrays that do not fit this simulation.
  void save_state(StateArchive& archive) const;
  void restore_state(StateArchive& archive);
  // Calls every observer now (for instance for the initial state).
  void observe_all();

  // Adds each term's forces to every cell's membrane forces of the latest step, which a step
  // computes as totals only (Cell::add_term_forces). Observers that declare needs_term_forces get
  // them without asking; call it before reading MembraneForces::terms elsewhere.
  void add_term_forces();

  // The fluid of the whole lattice. Across processes, a copy gathered for the observers that
  // declare reads_fluid, at the end of run() and for a failure dump: reading it at another step
  // throws std::logic_error.
  const lattice::FluidSolver& fluid() const;
  // Whether the fluid runs across several processes.
  bool distributed() const { return distributed_ != nullptr; }
  // The fluid across processes (null on one): this process's slab, which a parallel writer
  // (hdf5_snapshot.cpp) reads without gathering.
  const parallel::DistributedFluid* distributed_fluid() const { return distributed_.get(); }
  // Whether this process owns cell `index`: across processes, the one whose planes hold its
  // centroid, which writes the cell in its part of an HDF5 snapshot; on one process, every cell.
  bool owns_cell(std::size_t index) const;
  // Whether this process computes cell `index`'s membrane and hook forces, its contact search and
  // its friction solve for all (the others copy them): while every process holds every cell, the
  // cells are dealt out in contiguous runs of about equal vertex counts, so that the work is
  // balanced wherever the cells are (by their centroids, a tube along x cut into z-slabs would
  // give most cells to the process holding its axis). On one process, every cell.
  bool computes_cell(std::size_t index) const;
  // Across processes (collective): the distributed fluid's state copied into fluid() on every
  // process, unless it already holds this step's; nothing on one process.
  void gather_fluid();
  std::span<const Cell> cells() const { return cells_; }
  const Cell& cell(std::size_t index) const { return cells_.at(index); }
  // Where a cell's vertices are now (after the latest step), in um: what observers measure.
  std::vector<Vec3> positions_now_um(std::size_t cell_index) const;
  // Between steps: puts a cell's vertices at `positions_um`, at rest (Cell::move_to). Across
  // processes every process must pass the same positions (each holds a copy of the cell).
  void move_cell(std::size_t cell_index, std::span<const Vec3> positions_um);
  const units::UnitConverter& units() const { return units_; }
  const LatticeFrame& frame() const { return frame_; }
  const ibm::GridView& grid_view() const { return grid_; }
  const CouplingParameters& parameters() const { return parameters_; }
  std::size_t time_step() const { return time_step_; }
  double time_s() const;
  const StepPhaseTimes& phase_times() const { return phase_times_; }
  // ibm.sub_spacing_drag over the cells added so far (off: SubSpacingDragSummary::on false).
  SubSpacingDragSummary sub_spacing_drag_summary() const;
  void reset_phase_times() { phase_times_ = {}; }
  std::vector<std::size_t> capped_steps_per_cell() const;

 private:
  struct RegisteredObserver {
    Observer observer;
    std::optional<std::size_t> last_observed_step;
  };

  // Runs body(k) for every cell k, in parallel over the cells when there are several; then
  // fails (fail()) for the lowest-indexed cell whose body threw a RuntimeFailure, and rethrows
  // any other exception. Bodies may write only their own cell's state.
  template <class Body>
  void for_each_cell(const Body& body);
  // Runs body(k) for the cells `indices` (in parallel when there are several) and returns what
  // each threw (null for none), in the order of `indices`.
  template <class Body>
  std::vector<std::exception_ptr> run_on_cells(std::span<const std::size_t> indices,
                                               const Body& body);
  // Phase 1: every cell's membrane and external forces (the hooks).
  void compute_cell_forces();
  // Phase 1 across processes with several cells: each process computes its cells (computes_cell)
  // and takes the others' as copies (cell.hpp, adopt_forces). False, having adopted nothing, if a
  // cell failed on any process.
  bool compute_owned_cell_forces();
  // Collective: each process appends, for every cell of `computed` (the cells it computed), the
  // cell's index and append(k, values); every process then hands each cell's values to
  // adopt(k, values), which returns what follows, so that every copy of a cell holds what its
  // process computed. Throws std::logic_error unless `expected` cells came back (`what` names
  // the values).
  template <class Append, class Adopt>
  void share_computed_cells(std::span<const std::size_t> computed, std::size_t expected,
                            const char* what, const Append& append, const Adopt& adopt);
  // grow_cells: the growth's stage of the coming step in every cell's reference (at the start
  // of a step and between steps), and each cell's growth in this step (after the advance).
  void apply_growth();
  void grow_cell_shapes();
  void add_contact_forces();
  void build_contact_surfaces();
  void advance_fluid();
  void apply_membrane_friction();
  void apply_distributed_membrane_friction();
  // Adds the solves just made and their iterations to phase_times_ (StepPhaseTimes).
  void count_friction_iterations();
  // fail() for the lowest-indexed cell whose entry holds a RuntimeFailure; other exceptions go on
  // up (a bug, which stops the run). Returns if there is none.
  void fail_on_first(std::span<const std::exception_ptr> failures_by_cell);
  void advance_cells();
  void check_cells();
  void notify_due_observers();
  void notify(RegisteredObserver& registered);
  void notify_observers_of_final_state();
  std::optional<std::string> stop_reason();
  // Writes a checkpoint if the policy says one is due after this step.
  void checkpoint_if_due(std::chrono::steady_clock::time_point& last_checkpoint) const;
  // The observers see the state reached, a checkpoint is written, Interrupted thrown.
  [[noreturn]] void stop_interrupted();
  // Writes the failure dump (if there is a run directory) and throws RuntimeFailure.
  [[noreturn]] void fail(std::optional<std::size_t> cell, const std::string& reason);
  // Whether `local` holds on any process (collective across processes).
  bool on_any_process(bool local) const;

  // The undivided fluid; across processes its geometry, and a gathered copy of the state at
  // step fluid_gathered_step_ (none: not since a restore).
  std::unique_ptr<lattice::FluidSolver> fluid_;
  std::unique_ptr<parallel::DistributedFluid> distributed_;
  std::optional<std::size_t> fluid_gathered_step_ = 0;
  units::UnitConverter units_;
  CouplingParameters parameters_;
  LatticeFrame frame_;
  ibm::GridView grid_;
  const ibm::DeltaKernel* kernel_;
  const ibm::PointAdvanceScheme* advance_scheme_;
  double lattice_force_per_pN_;
  std::vector<Cell> cells_;
  std::vector<ForceCapMonitor> force_cap_monitors_;
  std::vector<ExternalForce> external_forces_;
  contact::ContactParameters contact_;
  contact::PeriodicBox contact_box_;
  contact::ContactWorkspace contact_workspace_;
  contact::ContactStatistics contact_statistics_;
  std::size_t close_contact_steps_ = 0;
  std::size_t capped_contact_steps_ = 0;
  // Every cell's vertices one after the other: the contact's input and output.
  std::vector<Vec3> contact_positions_um_;
  std::vector<std::uint32_t> contact_owners_;
  mutable std::vector<char> computed_here_;  // computes_cell's deal, per cell
  std::vector<Vec3> contact_forces_pN_;
  std::vector<std::array<std::uint32_t, 3>> contact_triangles_;  // the surface law's
  std::vector<std::uint32_t> contact_vertex_triangle_offsets_;
  std::vector<std::uint32_t> contact_vertex_triangles_;
  std::vector<ibm::SpreadSource> spread_sources_;  // one per cell, rebuilt every step
  std::vector<RegisteredObserver> observers_;
  std::vector<std::unique_ptr<StopCriterion>> stop_criteria_;
  std::optional<CytoplasmIndicator> cytoplasm_;  // when the fluid has a viscosity contrast
  // grow_cells: the growth, each cell's own (full-size) reference, and the stage its references
  // hold (none: to be set at the next step, as after a restore).
  CellGrowth growth_;
  std::vector<membrane::ReferenceState> full_references_;
  std::optional<std::size_t> applied_growth_stage_;
  bool forces_spread_ = false;
  std::size_t time_step_ = 0;
  StepPhaseTimes phase_times_;
  CheckpointPolicy checkpoint_policy_;
};

}  // namespace rbcsim::coupling
