// The lattice Boltzmann fluid driver: owns the arrays, composes collision, boundaries and forcing,
// and advances them with the kernel chosen by name. Everything is in lattice units (dx = dt = 1,
// rho ~ 1); core/units converts from SI.
//
// One step at time t: collide with the force density F(t) = force field + body force, stream.
// Afterwards density() and velocity() hold rho(t) and u(t) = (sum_i f_i c_i + F(t)/2) / rho(t) of
// that collision (Guo forcing): the velocity the immersed boundary interpolates after spreading
// F(t). The force field is zeroed after every step, ready for the next spread. Results do not
// depend on the number of OpenMP threads: every kernel gives each node to exactly one thread and
// reductions are order-independent (max) or summed in a fixed order.
//
// Curved walls. Voxelised walls sit half-way between a fluid node and its wall neighbour (a
// staircase). For walls that follow the geometry, choose an interpolated rule and give the solver
// the fraction q at which the wall cuts each fluid-to-wall link, computed from the wall shape by
// core/geometry (the grid there must have the solver's extents):
//   const geometry::LatticeGrid grid_um = geometry::lattice_around(shape, dx_um);
//   const geometry::SolidMask mask = geometry::voxelise(shape, grid_um);
//   FluidParameters parameters;
//   parameters.wall_rule = "bouzidi";
//   FluidSolver solver(LatticeGrid(grid_um.nx, grid_um.ny, grid_um.nz), parameters);
//   for (std::size_t node = 0; node < mask.size(); ++node) {
//     if (mask[node] == geometry::kSolid) solver.set_wall(node);
//   }
//   // ... inlet and outlet layers, if any ...
//   solver.set_wall_links(geometry::wall_link_fractions(shape, grid_um, mask));
// The nodes stay the staircase's; only the links' closure changes. Interpolated bounce-back does
// not conserve mass exactly (see tests/lattice/curved_wall_test.cpp for the measured drift).
#pragma once

#include "common/state_archive.hpp"
#include "common/vec3.hpp"
#include "lattice/collision.hpp"
#include "lattice/fluid_kernel.hpp"
#include "lattice/wall_link.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rbcsim::lattice {

struct FluidParameters {
  std::string collision = "trt";  // a name from collision_models()
  CollisionParameters collision_parameters;
  std::array<double, 3> body_force = {0.0, 0.0, 0.0};  // uniform force density
  // Lees-Edwards sliding periodic boundary in y with this velocity difference U between the image
  // above and the box (shear rate U / ny); empty: plain periodic.
  std::optional<double> lees_edwards_velocity;
  std::string kernel = "optimised";  // a name from fluid_kernels()
  // How wall links are closed: a name from wall_rules() (boundaries.hpp). Only links given to
  // set_wall_links differ from half-way bounce-back, whatever the rule.
  std::string wall_rule = "halfway";
  // Viscosity contrast (collision.hpp): the viscosity at indicator H = 1 over that at H = 0 (the
  // cytoplasm of cells over the plasma, `physics.cytoplasm_viscosity_ratio`). Anything but 1 gives
  // every node a viscosity class, 0 (the outer fluid) until set through viscosity_classes(); 1:
  // one viscosity everywhere, no classes, the uniform kernels.
  double inner_viscosity_ratio = 1.0;
  // Population storage (`lattice.precision`, fluid_kernel.hpp): single precision needs the
  // optimised kernel.
  Precision precision = Precision::double_precision;
};

struct SteadyStateCriterion {
  // Converged when, over one check interval, max_node |u(t) - u(t - interval)| is at most this
  // fraction of max_node |u(t)|.
  double relative_velocity_change = 1e-6;
  std::size_t check_interval = 100;
  std::size_t max_steps = 100000;
};

struct SteadyStateResult {
  bool converged = false;
  std::size_t steps = 0;  // steps taken by this call
  double relative_velocity_change = 0.0;
};

// Over some fluid nodes: the largest |u - u_previous|^2 and |u|^2 (lattice units). Maxima, so
// that slabs' values combine exactly in any order (parallel/distributed_fluid.hpp).
struct VelocityChangeSquared {
  double change = 0.0;
  double speed = 0.0;
};
// The criterion's measure from the maxima: max |u - u_previous| / max |u| (0 for a fluid at rest
// that stayed at rest, infinity for one that started moving from rest).
double relative_velocity_change(const VelocityChangeSquared& maxima);
// run_to_steady_state's loop for any solver: advance(steps) by check intervals, each followed by
// measure() (the relative velocity change, having checked the velocity is finite), until the
// criterion holds or max_steps were taken.
SteadyStateResult run_until_steady(const SteadyStateCriterion& criterion,
                                   const std::function<void(std::size_t)>& advance,
                                   const std::function<double()>& measure);

class FluidSolver {
 public:
  // Starts at rest at density 1, every node fluid. Throws rbcsim::InputError for an unknown
  // collision model, kernel or wall rule, or bad collision parameters.
  FluidSolver(LatticeGrid grid, FluidParameters parameters);
  ~FluidSolver();
  FluidSolver(const FluidSolver&) = delete;
  FluidSolver& operator=(const FluidSolver&) = delete;

  // Geometry, before the first step (later calls throw std::logic_error). Non-fluid nodes report
  // density 0 and their wall velocity.
  void set_wall(std::size_t node, const std::array<double, 3>& wall_velocity = {0.0, 0.0, 0.0});
  // The bounce-back-with-velocity inlet: a wall node moving at the inflow velocity of that node.
  void set_velocity_inlet(std::size_t node, const std::array<double, 3>& velocity);
  void set_pressure_outlet(std::size_t node, double density);
  // Where curved walls cut the links (WallLink), after the walls are set; links not given stay
  // half-way. Links whose node is not fluid or whose end node is not a wall here (for instance
  // those of inlet and outlet layers, which have their own rules) are skipped; returns how many
  // were taken. Throws rbcsim::InputError naming `lattice wall links` and the link for a node
  // outside the grid, a direction outside 1..18 or a fraction outside (0, 1].
  std::size_t set_wall_links(std::span<const WallLink> links);
  const BoundaryMap& boundaries() const { return setup_.boundaries; }
  const std::vector<std::uint8_t>& solid_mask() const { return setup_.boundaries.kinds(); }

  // Equilibrium populations at the fluid nodes; sets density and velocity accordingly.
  void initialise_equilibrium(double density, const std::array<double, 3>& velocity);
  void initialise_equilibrium(const std::vector<double>& density, const VectorField& velocity);
  // Pre-collision populations in natural layout (kDirections * node_count values, see
  // FluidArrays); density and velocity become their moments with the body force.
  void initialise_populations(const std::vector<double>& populations);

  // The force density field: add to it before step(). Taking it by non-const reference makes the
  // next step read it.
  VectorField& force_density();
  const VectorField& force_density() const { return arrays_.force_density; }

  void step();
  void advance(std::size_t steps);
  // Steps until the criterion holds or max_steps were taken. Throws rbcsim::RuntimeFailure on a
  // non-finite velocity, naming the step and the node.
  SteadyStateResult run_to_steady_state(const SteadyStateCriterion& criterion);
  // run_to_steady_state's measure over the fluid nodes [node_begin, node_end) (grid order), and
  // `previous` (a field of the grid's size) set to their velocity there.
  VelocityChangeSquared velocity_change_since(VectorField& previous, std::size_t node_begin,
                                              std::size_t node_end) const;
  // Throws rbcsim::RuntimeFailure, naming the step and the node, if a fluid node's velocity is
  // not finite (the flow went unstable).
  void require_finite_velocity() const;

  // Per-node viscosity, when parameters().inner_viscosity_ratio is not 1: the class of every node
  // (grid order), which the next steps read (solid nodes' classes are ignored). The caller owns
  // their values; they are not part of the checkpoint state (the coupled simulation recomputes
  // them from the cells before every step). Throws std::logic_error without a contrast.
  bool has_viscosity_contrast() const { return !class_rates_.empty(); }
  std::span<ViscosityClass> viscosity_classes();
  std::span<const ViscosityClass> viscosity_classes() const;

  const LatticeGrid& grid() const { return setup_.grid; }
  const FluidParameters& parameters() const { return parameters_; }
  // The rates of the outer fluid (viscosity class 0).
  RelaxationRates relaxation_rates() const { return rates_; }
  // The rates of every viscosity class (kViscosityClasses entries); empty without a contrast.
  std::span<const RelaxationRates> class_rates() const { return class_rates_; }
  // Kinematic viscosity (1/omega_even - 1/2) / 3 of the outer fluid.
  double viscosity() const;
  std::size_t time() const { return time_; }
  double lees_edwards_offset() const;

  const std::vector<double>& density() const { return arrays_.density; }
  const VectorField& velocity() const { return arrays_.velocity; }
  std::array<double, 3> velocity_at(std::size_t node) const;
  // Whether the populations are in natural layout between two steps (always with the reference
  // kernel; after every second step with the optimised one): only then can momentum be added.
  bool populations_natural() const { return arrays_.layout == PopulationLayout::natural; }
  // The density and momentum sum_i f_i c_i of the pre-collision populations of each node (what
  // the next collision starts from, without its force), between two steps. Throws
  // std::logic_error unless populations_natural().
  void pre_collision_moments(std::span<const std::size_t> nodes, std::span<double> density,
                             std::span<Vec3> momentum) const;
  // Adds momentum[k] (lattice units, rho u) to fluid node nodes[k] between two steps: each
  // pre-collision population f_i gains 3 w_i c_i . momentum, which keeps the node's mass and adds
  // exactly that momentum, and the velocity of the latest collision gains momentum / density (so
  // an interpolation now sees it). Throws std::logic_error unless populations_natural().
  void add_momentum(std::span<const std::size_t> nodes, std::span<const Vec3> momentum);
  // Sum of all populations of the fluid nodes, independent of the thread count.
  double total_mass() const;
  // Pre-collision populations in natural layout, whatever the kernel's current layout.
  std::vector<double> pre_collision_populations() const;

  // A range of nodes' populations as stored, for a halo exchange between processes
  // (core/parallel): nodes [first_node, first_node + count) in grid order, slot slots[s] of node
  // first_node + k at [s * count + k] (every slot 0..18 in order when `slots` is empty), in the
  // kernel's current layout and either precision (single precision's f_i - w_i as doubles,
  // exactly). Replacing them with what another solver's stored_populations gave makes these slots
  // that solver's, bit for bit. Throws std::out_of_range for a range past the grid, a slot outside
  // 0..18 or values of the wrong size.
  std::vector<double> stored_populations(std::size_t first_node, std::size_t count,
                                         std::span<const int> slots = {}) const;
  void replace_stored_populations(std::size_t first_node, std::size_t count,
                                  std::span<const double> values, std::span<const int> slots = {});

  // Checkpoints (common/state_archive.hpp): the populations as the kernel holds them and their
  // layout, the density and velocity of the latest collision, and the step count (the
  // Lees-Edwards offset follows it). Restored as is, so a resumed run is bit-identical after any
  // step count. The geometry is not saved: restore into a solver set up the same way (same
  // kernel). restore_state throws InputError (naming the archive) when an array's size does not
  // fit this grid or the layout is unknown.
  void save_state(StateArchive& archive) const;
  void restore_state(StateArchive& archive);

 private:
  void require_geometry_editable() const;
  void mark_boundary_node(std::size_t node);
  void ensure_kernel();
  // forced_spans_ := in each row of nodes, the span from the first to the last node with a
  // non-zero force density. A step reads and zeroes only those: a single cell forces a few nodes
  // of its lattice.
  void find_forced_spans();
  void zero_forced_spans();

  LatticeSetup setup_;
  FluidParameters parameters_;
  RelaxationRates rates_;
  // With a viscosity contrast: the rates of each class and the class of each node; else empty.
  std::vector<RelaxationRates> class_rates_;
  std::vector<ViscosityClass> viscosity_classes_;
  FluidArrays arrays_;
  std::unique_ptr<FluidKernel> kernel_;
  bool force_field_active_ = false;
  std::vector<ForcedSpan> forced_spans_;  // per row (y + ny z), for the step being made
  std::size_t time_ = 0;
};

}  // namespace rbcsim::lattice
