// Membrane viscosity in a coupled run (docs/physics.md, "Membrane viscosity"): the edge friction
// of membrane/edge_friction.hpp acts as an implicit momentum exchange among the fluid nodes under
// the membrane, not as a force spread explicitly. At the paper's lattice the friction is about
// 150 times stiffer than an explicit coupling can integrate (eta_m dt / (rho dx^3) ~ 150 at
// 0.5 Pa s um, dx 0.5 um, tau 1); a backward-Euler step of it on the fluid is stable at any
// stiffness:
//   (rho + dt S^T Gamma S) u' = rho u,
// u the velocities of the nodes the cell's stencil reaches, S the stencil's interpolation onto the
// vertices (S^T its spreading), Gamma the friction operator of the membrane's edges at the current
// positions, dt in lattice steps. The membrane then moves with S u', the fluid keeps no slip, the
// momentum exchanged, rho (u' - u) = -dt S^T Gamma S u', sums to zero, and the kinetic energy can
// only fall. u is the velocity the next collision will see: Guo's (m + F/2) / rho of the
// populations after streaming, with F, not known until the next spread, taken as the force of the
// collision just made (LatestForce). Without F/2 the membrane moves F/(2 rho) behind the fluid at
// every solve, and a cell whose volume term pushes outwards creeps inwards, the faster the more it
// has lost (a physiological cell in shear, solved every step, lost 10 % of its volume in 13 000
// steps). Conjugate gradients on the nodes (3x3 block-diagonal preconditioner), serial, sums in
// a fixed order. Each solve starts from u plus the correction u' - u extrapolated from the last two
// solves (c1 + (c1 - c2), or c1 where the older solve lacks the node) at the nodes they share (the
// friction's correction changes little and smoothly from one step to the next: in a 10 um tube run
// 102-109 iterations instead of 260 per solve from c1, 17 % fewer again from the line),
// converging to the same tolerance, relative to the residual at u' = u; both corrections ride in
// checkpoints, so a resumed run is the straight one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/state_archive.hpp"
#include "common/vec3.hpp"
#include "ibm/interpolation_stencil.hpp"
#include "lattice/fluid_solver.hpp"
#include "membrane/edge_friction.hpp"

namespace rbcsim::coupling {

struct ImplicitFrictionSettings {
  // Converged when the residual is below this fraction of the first one (that of u' = u). Runs
  // take membrane.viscosity_solve_tolerance instead.
  double relative_tolerance = 1e-6;
  std::size_t max_iterations = 1000;
};

// The force density of the fluid's latest collision as the cell sees it, in lattice units: its
// own vertex forces (one per stencil point, spread by the stencil the solve uses; empty: none) and
// the uniform body force. Other cells' forces at shared nodes are not included (they meet this
// cell's solve a step late, as their friction does).
struct LatestForce {
  std::span<const Vec3> vertex_forces_lu;
  Vec3 body_force_lu = Vec3::Zero();
};

class ImplicitMembraneFriction {
 public:
  // One step over `dt_steps` lattice steps: solve, then add_momentum_to.
  std::size_t apply(const ibm::InterpolationStencil& stencil, std::span<const Vec3> positions_lu,
                    const membrane::EdgeNetwork& network,
                    const membrane::EdgeFrictionParameters& friction_lu, double dt_steps,
                    lattice::FluidSolver& fluid, const LatestForce& latest_force,
                    std::span<Vec3> membrane_velocities_lu,
                    const ImplicitFrictionSettings& settings = {});

  // Solves for u' on the stencil's nodes of `fluid` (its populations in natural layout), writes
  // S u' into `membrane_velocities_lu` and keeps the momentum the step exchanges with those nodes;
  // the fluid is only read, so the cells of a suspension solve in parallel on one fluid state.
  // `friction_lu` in lattice force per lattice velocity. Returns the iterations; throws
  // RuntimeFailure when max_iterations do not reach the tolerance.
  std::size_t solve(const ibm::InterpolationStencil& stencil, std::span<const Vec3> positions_lu,
                    const membrane::EdgeNetwork& network,
                    const membrane::EdgeFrictionParameters& friction_lu, double dt_steps,
                    const lattice::FluidSolver& fluid, const LatestForce& latest_force,
                    std::span<Vec3> membrane_velocities_lu,
                    const ImplicitFrictionSettings& settings = {});
  // Adds the latest solve's momentum to `fluid` (FluidSolver::add_momentum).
  void add_momentum_to(lattice::FluidSolver& fluid) const;

  // The same solve in two halves, for a fluid held elsewhere (the distributed lattice, where the
  // nodes under a cell lie on several processes): prepare() finds the stencil's nodes, sorted
  // (nodes()); solve_with_moments() then solves from their pre-collision density and momentum
  // (FluidSolver::pre_collision_moments of nodes()), exactly as solve() does.
  void prepare(const ibm::InterpolationStencil& stencil);
  std::span<const std::size_t> nodes() const { return nodes_; }
  std::size_t solve_with_moments(std::span<const Vec3> positions_lu,
                                 const membrane::EdgeNetwork& network,
                                 const membrane::EdgeFrictionParameters& friction_lu,
                                 double dt_steps, std::span<const double> density,
                                 std::span<const Vec3> momentum_lu, const LatestForce& latest_force,
                                 std::span<Vec3> membrane_velocities_lu,
                                 const ImplicitFrictionSettings& settings = {});
  // The latest solve's momentum per node of nodes() (lattice units, rho u), to add to the fluid.
  std::span<const Vec3> momentum() const { return momentum_; }
  // The latest solve as values, for the copies of this cell on other processes: append_solution
  // adds the momentum and the correction per node of nodes() to `values`; adopt_solution, after
  // prepare() on the same stencil, takes them as if this copy had solved, and returns what
  // follows. Throws std::invalid_argument for values too short.
  void append_solution(std::vector<double>& values) const;
  std::span<const double> adopt_solution(std::span<const double> values);

  // The previous solve's nodes and correction (the next solve's start), under `prefix`.
  void save_state(StateArchive& archive, const std::string& prefix) const;
  void restore_state(StateArchive& archive, const std::string& prefix);

 private:
  // Adds the previous solve's correction c1 to `velocity` (one per node of nodes_) at the nodes
  // both share, and where the solve before that (c2) shares the node too, c1 - c2: the correction
  // extrapolated linearly from the last two solves. False when the previous solve shares no node
  // (the first solve).
  bool add_previous_correction(std::span<Vec3> velocity) const;
  // The previous correction becomes the older one (once after each prepare()); previous_nodes_ :=
  // nodes_, its correction sized for them (to be filled).
  void keep_correction();

  // The stencil's nodes, sorted, and for every vertex slot the index of its node among them.
  // 32-bit slot indices: one cell's slots are far fewer than 2^32, and they halve the index
  // traffic of the solve's gathers.
  std::vector<std::size_t> nodes_;
  std::vector<std::uint32_t> slot_node_;
  std::vector<double> slot_weight_;
  std::vector<std::uint32_t> slot_offsets_;  // vertex v's slots: [v], [v + 1]
  // The same slots grouped by node: node k's are [k], [k + 1] of the offsets, vertices ascending.
  std::vector<std::uint32_t> node_slot_offsets_;
  std::vector<std::uint32_t> node_slot_vertex_;
  std::vector<double> node_slot_weight_;
  // prepare()'s work arrays, kept so that a step does not allocate: per slot its lattice node
  // and vertex, and the slots in node order.
  std::vector<std::size_t> slot_lattice_node_;
  std::vector<std::uint32_t> slot_vertex_;
  std::vector<std::uint32_t> slot_order_;
  std::vector<std::uint32_t> sort_scratch_;
  std::vector<Vec3> momentum_;  // per node of nodes_: the latest solve's exchange
  // The latest solve's nodes (sorted) and u' - u at each: the next solve's start.
  std::vector<std::size_t> previous_nodes_;
  std::vector<Vec3> previous_correction_;
  // The solve's before that: with the latest, a line to extrapolate the next start along.
  std::vector<std::size_t> older_nodes_;
  std::vector<Vec3> older_correction_;
  bool correction_kept_ = false;  // keep_correction() has shifted the history since prepare()
};

}  // namespace rbcsim::coupling
