// One cell of a coupled simulation (docs/architecture.md): its membrane model, where its vertices
// are, and the arrays each step fills. Vertex positions live in lattice units (node (i, j, k) at
// (i, j, k)), where the immersed boundary works; the membrane works in um and pN, so each step
// converts once each way. The driver (coupled_simulation.hpp) calls the phases in order.
//
// Positions are never wrapped into a periodic box: the IBM wraps node indices instead, so a
// cell's shape and distance travelled stay continuous.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/state_archive.hpp"
#include "common/vec3.hpp"
#include "coupling/membrane_friction.hpp"
#include "coupling/sub_spacing_drag.hpp"
#include "coupling/volume_hold.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"
#include "ibm/interpolation_stencil.hpp"
#include "ibm/point_advance.hpp"
#include "ibm/transfer.hpp"
#include "lattice/fluid_kernel.hpp"
#include "lattice/fluid_solver.hpp"
#include "membrane/membrane_model.hpp"

namespace rbcsim::coupling {

// Where the lattice sits in space: node (i, j, k) at origin_um + dx_um * (i, j, k), the
// node-centred convention of the geometry module (geometry/lattice_grid.hpp); one lattice
// velocity is dx_um / dt_s, one pN is lattice_force_per_pN lattice forces.
struct LatticeFrame {
  Vec3 origin_um = Vec3::Zero();
  double dx_um = 1.0;
  double dt_s = 1.0;
  double lattice_force_per_pN = 1.0;

  Vec3 to_lattice(const Vec3& position_um) const { return (position_um - origin_um) / dx_um; }
  Vec3 to_um(const Vec3& position_lu) const { return origin_um + dx_um * position_lu; }
};

class Cell {
 public:
  // `positions_um` holds one initial position per vertex of the model (usually the stress-free
  // mesh itself, placed in the domain). Throws std::invalid_argument for a count mismatch.
  Cell(membrane::MembraneModel model, std::span<const Vec3> positions_um, const LatticeFrame& frame,
       const ibm::PointAdvanceScheme& advance_scheme);

  const membrane::MembraneModel& model() const { return model_; }
  std::size_t vertex_count() const { return positions_lu_.size(); }

  std::span<const Vec3> positions_lu() const { return positions_lu_; }
  // Where the latest forces were computed (um): the positions at the start of the latest step.
  std::span<const Vec3> positions_um() const { return positions_um_; }
  // The positions before the latest advance, lattice units.
  std::span<const Vec3> previous_positions_lu() const { return previous_positions_lu_; }
  const membrane::MembraneForces& membrane_forces() const { return membrane_forces_; }
  std::span<const Vec3> external_forces_pN() const { return external_forces_pN_; }
  // Membrane (capped) plus external force per vertex: what the latest step spread, pN.
  std::span<const Vec3> total_forces_pN() const { return total_forces_pN_; }
  // The velocity the vertices moved with in the latest step, lattice units: the fluid's,
  // interpolated (or the friction step's), less the volume hold's correction if it holds.
  std::span<const Vec3> velocities_lu() const { return velocities_lu_; }
  // With membrane viscosity: the vertex velocities of the latest implicit friction step (the
  // membrane's velocity S u' there, lattice units) and the conjugate-gradient iterations it took.
  std::span<const Vec3> membrane_velocities_lu() const { return membrane_velocities_lu_; }
  std::size_t friction_iterations() const { return friction_iterations_; }
  // Mean vertex position, summed in vertex order (thread-count independent), lattice units.
  Vec3 centroid_lu() const;

  // Step phase 1: membrane forces at the current positions (the external forces are zeroed, for
  // the driver's hooks to add to), the totals only unless `detail` asks for every term's too.
  // Throws RuntimeFailure from the membrane (a deviation at its limit, a non-finite force).
  void compute_membrane_forces(const LatticeFrame& frame,
                               membrane::ForceDetail detail = membrane::ForceDetail::totals);
  // Adds each term's forces to the latest step's membrane forces, if they lack them: the same
  // evaluation again with the detail (the totals come out bit-identical, membrane_forces.hpp),
  // and with membrane viscosity its friction at membrane_velocities_lu(), which the totals then
  // include (the step exchanged it with the fluid implicitly, not through the spread).
  void add_term_forces(const LatticeFrame& frame);
  std::span<Vec3> external_forces_pN() { return external_forces_pN_; }
  // Phase 1's results as values, for the copies of this cell on other processes (the coupled loop
  // across processes): the membrane's totals, capped count and deviations, and the external
  // forces. append_forces adds them to `values`; adopt_forces reads them from `values` (as
  // compute_membrane_forces and the hooks would have left them, the terms' detail dropped) and
  // returns what follows. Throws std::invalid_argument for values too short.
  void append_forces(std::vector<double>& values) const;
  std::span<const double> adopt_forces(std::span<const double> values, const LatticeFrame& frame);
  // Phase 2: total = membrane + external, in lattice force units, and the stencil of this step,
  // built once and used by the spread and the interpolation. Throws RuntimeFailure for a
  // non-finite total force, or from the stencil (a vertex with no fluid node in reach).
  void prepare_spread(double lattice_force_per_pN, const ibm::DeltaKernel& kernel,
                      const ibm::GridView& grid, const std::uint8_t* solid_mask);
  // What the driver spreads for this cell (ibm::spread_forces), after prepare_spread.
  ibm::SpreadSource spread_source() const { return {&stencil_, forces_lu_}; }
  // After the fluid step, with membrane viscosity and the fluid's populations in natural layout:
  // the implicit friction step on the fluid under the membrane (membrane_friction.hpp), over the
  // steps since the previous one; `time_step` counts the steps completed. In two halves: the
  // solve only reads the fluid (cells solve in parallel), then its momentum is added (cell after
  // cell). Both do nothing without membrane viscosity or with the populations swapped. Throws
  // RuntimeFailure when the solve does not converge.
  bool has_membrane_friction() const;
  void solve_membrane_friction(const lattice::FluidSolver& fluid, const LatticeFrame& frame,
                               std::size_t time_step);
  void add_membrane_friction(lattice::FluidSolver& fluid) const;
  // The same step in parts, for the distributed lattice, where the nodes under a cell lie on
  // several processes (CoupledSimulation): prepare_membrane_friction() gives the nodes the solve
  // acts on (global indices, sorted); solve_membrane_friction_with() solves from their
  // pre-collision density and momentum (and the fluid's body force) as
  // solve_membrane_friction() would from the fluid;
  // append_friction_solution() and adopt_friction_solution() (after prepare_membrane_friction()
  // on the copy) make a copy of the cell on another process hold that solve, bit for bit;
  // membrane_friction_momentum() is the momentum to add per node of the solve. Throws as
  // solve_membrane_friction and ImplicitMembraneFriction::adopt_solution.
  std::span<const std::size_t> prepare_membrane_friction();
  void solve_membrane_friction_with(std::span<const double> density,
                                    std::span<const Vec3> momentum_lu,
                                    const std::array<double, 3>& body_force_lu,
                                    const LatticeFrame& frame, std::size_t time_step);
  void append_friction_solution(std::vector<double>& values) const;
  std::span<const double> adopt_friction_solution(std::span<const double> values,
                                                  std::size_t time_step);
  std::span<const Vec3> membrane_friction_momentum() const { return friction_.momentum(); }
  // From now on every advance holds the enclosed volume (volume_hold.hpp, `ibm.hold_volume`):
  // the vertices move with the velocities less a multiple of the volume gradient.
  void hold_volume();
  // Growth in the flow (CoupledSimulation::grow_cells): the membrane's stress-free reference
  // becomes `reference` (the model's connectivity), and the sub-spacing drag's rate is found
  // again for it. Between steps.
  void set_reference(membrane::ReferenceState reference, const LatticeFrame& frame);
  // Scales the vertex positions by `factor` about their centroid, after an advance: a growing
  // cell's own growth in the step, on top of the flow's motion.
  void dilate(double factor);
  // From now on every advance adds the drag on the membrane's sub-spacing modes
  // (sub_spacing_drag.hpp, `ibm.sub_spacing_drag`) for fluids of viscosities summing to
  // `viscosity_sum_lu` (eta_out + eta_in, lattice units) on the two sides; raised, where the
  // membrane's stiffness at its current shape would relax a mode by more than
  // kMaxDragRatePerStep in one step, until it does not. The explicit step multiplies a mode by
  // 1 - rate: at 1 the fastest mode is gone in one step, beyond 2 it grows.
  void use_sub_spacing_drag(double viscosity_sum_lu, const LatticeFrame& frame);
  static constexpr double kMaxDragRatePerStep = 1.0;
  // The fastest relaxation per step of the drag at the physical viscosities (0 without it): above
  // kMaxDragRatePerStep the drag used is that many times stronger.
  double sub_spacing_drag_rate() const { return drag_rate_per_step_; }
  // How many times the fluids' viscosity the drag uses: 1 unless it was raised as above.
  double sub_spacing_drag_raised_by() const { return drag_raised_by_; }
  // Phases 4-5: interpolates `velocity` with the same stencil, then moves the vertices (dt = 1).
  void interpolate_and_advance(const ibm::GridView& grid, const lattice::VectorField& velocity);
  // The same with the velocities interpolated elsewhere (on the distributed lattice,
  // parallel/distributed_ibm.hpp), one per vertex, with stencil().
  void advance_with(std::span<const Vec3> interpolated_velocities_lu);
  // The stencil of the latest prepare_spread.
  const ibm::InterpolationStencil& stencil() const { return stencil_; }

  // Puts the vertices at `positions_um` at rest, between steps, as if the cell had been added
  // there: the previous positions are these, the velocities zero, the point advance without
  // history (a shape found outside the coupled loop, the fluid stretch's warm start). Throws
  // std::invalid_argument for a count mismatch.
  void move_to(std::span<const Vec3> positions_um, const LatticeFrame& frame);

  // Checkpoints, between steps: positions (current and previous), the latest velocities and the
  // point-advance history, each array named `<prefix>...`. Forces are not saved: the next step
  // computes them from the positions.
  void save_state(StateArchive& archive, const std::string& prefix) const;
  void restore_state(StateArchive& archive, const std::string& prefix, const LatticeFrame& frame);

 private:
  membrane::MembraneModel model_;
  std::vector<Vec3> positions_lu_;
  std::vector<Vec3> previous_positions_lu_;
  std::vector<Vec3> positions_um_;
  membrane::MembraneWorkspace workspace_;
  membrane::MembraneForces membrane_forces_;
  std::vector<Vec3> external_forces_pN_;
  std::vector<Vec3> total_forces_pN_;
  std::vector<Vec3> forces_lu_;
  std::vector<Vec3> velocities_lu_;
  // With membrane viscosity (solve_membrane_friction, add_membrane_friction).
  ImplicitMembraneFriction friction_;
  std::vector<Vec3> membrane_velocities_lu_;
  std::size_t last_friction_step_ = 0;
  bool friction_applied_ = false;  // in this step, so the advance takes its velocities
  std::size_t friction_iterations_ = 0;
  ibm::InterpolationStencil stencil_;
  ibm::PointAdvancer advancer_;
  std::optional<VolumeHold> volume_hold_;
  std::optional<SubSpacingDrag> sub_spacing_drag_;
  double drag_viscosity_sum_lu_ = 0.0;
  double drag_rate_per_step_ = 0.0;
  double drag_raised_by_ = 1.0;
  double drag_fluid_viscosity_sum_lu_ = 0.0;  // the fluids' (use_sub_spacing_drag's argument)

  // Phase 5 from velocities_lu_ (or the friction step's velocities), with the volume hold.
  void advance();
  // The membrane's friction coefficients in lattice force per lattice velocity.
  membrane::EdgeFrictionParameters friction_lu(const LatticeFrame& frame) const;
  ImplicitFrictionSettings friction_settings() const;
  // The force of the fluid's latest collision as this cell spread it, plus the body force.
  LatestForce latest_force(const std::array<double, 3>& body_force_lu) const;
};

}  // namespace rbcsim::coupling
