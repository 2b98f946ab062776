// One cell in simple shear flow, swept over shear rates (paper §3.2,
// Figs. 9-11: the experiment of Bessis & Mohandas 1975).
//
//   auto cell = in_shear_frame(mesh);                      // symmetry axis along y, centred
//   membrane::MembraneModel model(cell, parameters);        // the stress-free reference
//   auto plans = plan_shear_rates(model, cell, engine, settings);   // throws on unsafe lattices
//   auto points = run_shear_sweep(model, cell, engine, settings, plans, threads, observer);
//
// Frame: flow along x, velocity gradient along y (u_x = rate * y about the box centre),
// vorticity along z. The cell starts at rest at the centre of the box with its symmetry axis along
// y: perpendicular to the flow and in the shear plane. The box is periodic in x and z; in y it is
// bounded by a named boundary (one table, shear_case.cpp):
//   "lees-edwards"  sliding periodic images (the paper's "periodic in all directions, top moving
//                   in +x"), box height = gap;
//   "walls"         two bounce-back walls moving at -/+ rate * gap / 2, the gap between them.
// The fluid starts with the linear profile, so only the cell's disturbance has to develop.
//
// Time scales (the viscosity trick). The membrane has no mass, and its viscosity (if any) and the
// cytoplasm's are fixed ratios to the medium's, so the steady shape depends only on the capillary
// number Ca = mu_medium * rate * R / G_s, as long as the cell Reynolds number
// Re = rate * R^2 / nu stays << 1. Simulating rate * s with the viscosity divided by s (the
// membrane's too) keeps Ca;
// the lattice shear rate grows by s^2 (dt grows by s), so the steps per unit strain drop by s^2,
// and Re grows by s^2. With viscosity_scaling the case picks the largest s >= 1 that keeps
// Re <= max_reynolds_number: every low rate then costs as few steps per strain as the
// Reynolds limit allows. Times and frequencies are converted back to the physical rate.
// Mach: the largest fluid speed, rate * gap / 2, must stay below 0.1 lattice units (InputError).
//
// Steady state. A red cell in shear tank-treads with swinging: its length, breadth and
// inclination oscillate twice per turn of the membrane and never settle to constants, so the
// steady state is periodic and is judged on means. The shape is sampled four times per
// check_interval_strain; at every check the means of length and breadth over the last window are
// compared with those over the window before, and the rate is steady when both differ by less
// than steady_tolerance_per_strain of themselves per unit strain between the windows' centres, at
// three checks in a row. A window is the last half turn of a tracked membrane point (one
// period of the swinging: cases::samples_in_last_half_turn), one check interval at least; at rate
// 0 (the cell at rest, no turning) one check interval. The reported shape is the mean over the last
// window, with the length's swing in it (an ektacytometer's diffraction pattern is such a mean); a
// rate that ends before a whole window reports its final shape. A rate that is not steady by
// max_strain is reported with steady = false, never as steady.
// Rate 0 runs with the physical viscosity for as many steps as a rate at the Reynolds limit takes
// per strain, its "strain" counted in that time unit.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cases/shear_observables.hpp"
#include "coupling/coupled_simulation.hpp"
#include "lattice/fluid_solver.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/geometry.hpp"
#include "mesh/triangle_mesh.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::cases {

struct ShearSettings {
  std::vector<double> rates_per_s;
  std::string boundary = "lees-edwards";  // a name of shear_boundary_names()
  // Box height (lees-edwards) or wall gap (walls), in cell diameters (the reference length).
  double gap_diameters = 3.0;
  // Periodic box length along x and z, in cell diameters.
  double width_diameters = 2.0;
  double max_strain = 60.0;  // rate * time after which a rate is reported steady = false
  double steady_tolerance_per_strain = 2e-3;
  double check_interval_strain = 1.0;
  bool viscosity_scaling = true;
  double max_reynolds_number = 0.1;
};

// The medium and the engine: lattice.*, physics.*, ibm.*, stability.* of the config.
struct ShearEngine {
  units::LatticeParameters lattice;  // the medium's physical kinematic viscosity
  lattice::FluidParameters fluid;
  // run_directory: failure dumps of rate i go to <run_directory>/rate_<i>/failure
  // (shear_rate_directory).
  coupling::CouplingParameters coupling;
};

std::vector<std::string> shear_boundary_names();

// "rate_<i>" (three digits at least): rate i's subdirectory of a run directory (failure dumps,
// checkpoints).
std::string shear_rate_directory(std::size_t rate_index);

// The box in lattice nodes: x and z periodic, width_diameters cell diameters (the largest vertex
// distance of `cell`) long; along y the gap of gap_diameters diameters plus the boundary's wall
// layers (one node per side for "walls", whose half-way walls sit half a node inside them).
struct ShearBox {
  int nx = 0, ny = 0, nz = 0;
  int wall_layers = 0;  // per side
  int gap_nodes() const { return ny - 2 * wall_layers; }
};

// Throws InputError naming shear.boundary for an unknown boundary.
ShearBox shear_box(const mesh::TriangleMesh& cell, double dx_um, const ShearSettings& settings);

// The fluid of a shear run, lattice units: the named boundary imposing shear_rate_lu across the
// gap (u_x = rate (y - (ny - 1) / 2), zero at the box centre) and that linear profile as the
// initial state. Throws InputError for an unknown boundary.
std::unique_ptr<lattice::FluidSolver> shear_fluid(const ShearBox& box,
                                                  const lattice::FluidParameters& parameters,
                                                  std::string_view boundary_name,
                                                  double shear_rate_lu);

// The stress-free mesh centred at the origin with its symmetry axis (the principal axis of least
// variance) along y. The built-in shapes have it along z already and are only rotated about x;
// any other mesh is first aligned with its principal axes.
mesh::TriangleMesh in_shear_frame(mesh::TriangleMesh mesh);

// Small-strain shear modulus of the link network, N/m: sqrt(3)/4 of the edge spring constant
// k_l kBT (1 + 1/tau_l^2) / (p L0) (Eq. 6 linearised; hexagonal network, as in
// share/reference/membrane_constants.csv), L0 the mean reference edge length. The area term
// keeps areas and adds nothing in pure shear. 0 without the link term.
double link_shear_modulus_N_per_m(const membrane::MembraneModel& model);

// What one rate simulates (the viscosity trick above).
struct ShearRatePlan {
  double shear_rate_per_s = 0.0;  // physical
  double simulated_shear_rate_per_s = 0.0;
  double simulated_kinematic_viscosity_m2_per_s = 0.0;
  double viscosity_scale = 1.0;   // simulated rate / physical rate = physical nu / simulated nu
  double reynolds_number = 0.0;   // simulated: rate R^2 / nu (R = half the reference length)
  double capillary_number = 0.0;  // mu_medium rate R / G_s: the same physical and simulated
  double strain_rate_lu = 0.0;    // the simulated rate (rate 0: the time unit) times dt
};

// One plan per rate. Throws InputError for a negative rate or a lattice speed above the Mach
// limit (naming the rate).
std::vector<ShearRatePlan> plan_shear_rates(const membrane::MembraneModel& model,
                                            const mesh::TriangleMesh& cell,
                                            const ShearEngine& engine,
                                            const ShearSettings& settings);

// The cell's shape at one instant of a rate's run.
struct ShearSample {
  double strain = 0.0;  // simulated rate * simulated time, as ShearPoint::strain
  ShearShape shape;
};

struct ShearPoint {
  ShearRatePlan plan;
  // Averaged over the last window of the steady-state check (window_strain of strain); the
  // shape at the end of the run if it ended before a whole window (window_strain 0).
  ShearShape shape;
  double length_swing_um = 0.0;  // largest minus smallest length over that window
  double window_strain = 0.0;
  double tank_treading_hz = 0.0;  // physical; 0 at rate 0
  double smoothness_rad = 0.0;    // dihedral_change_rms_rad: overall and mesh-scale bending
  double roughness_rad = 0.0;     // dihedral_roughness_rad: the mesh-scale part only
  // Of the final shape against the stress-free one: how near the local-area term's limit.
  mesh::AreaStrain area_strain;
  bool steady = false;
  double strain = 0.0;  // simulated rate * simulated time (rate 0: in its time unit)
  double time_s = 0.0;  // physical time: the simulated time times the viscosity scale
  std::size_t steps = 0;
  std::size_t force_cap_steps = 0;  // steps in which the vertex force cap clamped a vertex
  coupling::SubSpacingDragSummary sub_spacing_drag;
  std::string stop_reason;
  std::string failure;       // empty unless the run failed (instability): then steady = false
  bool interrupted = false;  // Ctrl-C: failure says so; the shape is the one reached
  double wall_time_s = 0.0;
  // The shape every check_interval_strain / 4 of strain from the first sample (a resumed rate:
  // from its checkpoint). Not kept in point.json: a completed point read back has none.
  std::vector<ShearSample> history;
};

// Called when a rate ends, with its index in settings.rates_per_s, from the thread that ran it.
using ShearObserver = std::function<void(std::size_t rate_index, const ShearPoint& point,
                                         const coupling::CoupledSimulation& simulation)>;

// What a caller adds to a sweep, all optional: `finished` sees each rate that ended (not failed,
// not interrupted); `configure` gets each rate's simulation, built, before it runs (checkpoint
// policy, resume); a rate with a `completed` point (index = rate index) is not run again but
// reported as that point (a resumed sweep). The tank-treading record and the steady-state
// checks ride in the rate's checkpoints, so a resumed rate ends as a straight one.
struct ShearHooks {
  ShearObserver finished;
  std::function<void(std::size_t rate_index, coupling::CoupledSimulation& simulation)> configure;
  std::vector<std::optional<ShearPoint>> completed;
};

// Runs one rate: builds the fluid and the coupled simulation, runs it to a steady state or
// max_strain. An instability is recorded in ShearPoint::failure (the dump is written), not
// thrown.
ShearPoint run_shear_rate(const membrane::MembraneModel& model, const mesh::TriangleMesh& cell,
                          const ShearEngine& engine, const ShearSettings& settings,
                          const ShearRatePlan& plan, std::size_t rate_index,
                          const ShearHooks& hooks);

// Every rate, `rate_threads` at a time (each simulation single-threaded then; results are the
// same as one by one, every phase being deterministic); across processes
// (engine.coupling.processes) one at a time. One point per rate, in order. After an
// interrupt (common/interrupt.hpp) the rates not yet started are reported interrupted, unrun.
std::vector<ShearPoint> run_shear_sweep(const membrane::MembraneModel& model,
                                        const mesh::TriangleMesh& cell, const ShearEngine& engine,
                                        const ShearSettings& settings,
                                        const std::vector<ShearRatePlan>& plans, int rate_threads,
                                        const ShearHooks& hooks);

}  // namespace rbcsim::cases
