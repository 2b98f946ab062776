// The optical-tweezers stretch (paper §3.1; docs/physics.md): a total force F pulls each
// of two contact patches at the ends of the cell's long axis in opposite directions; for each F
// the cell is brought to its steady shape and the axial and transverse diameters are recorded.
//
//   auto cell = prepare_stretch_cell(mesh, settings.contact);     // frame + patches
//   membrane::MembraneModel model(cell.mesh, parameters);         // the stress-free reference
//   auto run = run_stretch(model, cell, settings, observer);      // every force, in order
//
// How the steady shape is reached is a named mode (one table, stretch_case.cpp):
//   "quasi-static"  the membrane alone relaxed to equilibrium under the tweezer forces
//                   (quasi_static_stretch.hpp): no fluid, seconds.
//   "fluid"         the cell in a periodic box of fluid at rest, LBM + IBM, each force run to
//                   the steady state of the diameters (fluid_stretch.hpp): minutes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "cases/contact_patches.hpp"
#include "common/vec3.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling/snapshot.hpp"
#include "coupling/stop_criteria.hpp"
#include "lattice/fluid_solver.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/relaxation.hpp"
#include "mesh/triangle_mesh.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::cases {

// The "fluid" mode (fluid_stretch.hpp). The equilibrium under a static load does not depend on
// the fluid's viscosity, but the number of steps to reach it grows as nu^2 (dt ~ dx^2 / nu at
// fixed tau, relaxation time ~ rho nu): the stretch's fluid has its own viscosity.
struct FluidStretchSettings {
  // dx, tau, density and the stretch's kinematic viscosity (not physics.plasma_*).
  units::LatticeParameters lattice{0.5, 1.0, 1025.0, 1.1e-6};
  lattice::FluidParameters fluid;
  coupling::CouplingParameters coupling;
  // Gap between the resting cell and the periodic box's faces on every side; along the pull axis
  // the box also holds the cell at twice its rest length (Mills et al.: 1.97 at 193 pN).
  double box_margin_um = 3.0;
  // The tweezers move from one force to the next linearly over this time, as a trap is moved:
  // a jump would pull the patch faster than the membrane around it can follow (a transient
  // strain beyond the force laws' limits at low viscosity).
  double force_ramp_time_s = 1e-3;
  // Start each force from the membrane's equilibrium under it, found by the quasi-static
  // relaxation (StretchSettings::relaxation) from the shape reached, instead of ramping to it:
  // the coupled run then only has to settle the difference (the fluid-held volume, the lattice),
  // and its steady state is still the criterion of the point. A relaxation that does not
  // converge leaves the shape as it was and the force is ramped as without it.
  bool warm_start = false;
  // Each force runs until both diameters are steady (coupling::stop_at_steady_state) ...
  coupling::SteadyStateTolerance steady{
      .relative_rate_per_s = 0.5, .check_interval_s = 2e-4, .consecutive_checks = 3};
  // ... or for this long, after which its point is not converged and the run reports it.
  double max_time_per_force_s = 0.05;
  // Membrane .vtp time series (vtk/, cell0.pvd) every so often; 0: the per-force shapes only.
  double snapshot_interval_s = 0.0;
  // Or, with hdf5, h5/ and cells.xdmf (coupling/snapshot.hpp).
  coupling::SnapshotFormat snapshot_format = coupling::SnapshotFormat::vtk;
  // Where failure dumps, the time series and the final fluid.vti go; empty: nowhere.
  std::filesystem::path output_directory;
  // Called once with the simulation built (cell, tweezers, observers, stop criteria), before the
  // first force: a checkpoint policy, a resume (the run then continues at the checkpoint's force
  // and step, with the points measured before it; fluid_stretch.hpp). Empty: nothing.
  std::function<void(coupling::CoupledSimulation&)> configure;
};

struct StretchSettings {
  std::string mode = "quasi-static";
  std::vector<double> forces_pN;  // applied in this order, each from the previous shape
  ContactSettings contact;
  // quasi-static: the relaxation method by name (relaxation_methods.hpp) and its stop criterion
  // (force_tolerance_pN on the largest net vertex force, max_iterations).
  std::string relaxation = "fire";
  membrane::RelaxationSettings relaxation_settings{.force_tolerance_pN = 1e-4};
  FluidStretchSettings fluid;
};

// The cell in the stretch frame (stretch_geometry.hpp) and its contact patches.
struct StretchCell {
  mesh::TriangleMesh mesh;
  ContactPatches patches;
};

// Throws InputError for an unknown contact rule or patches that overlap.
StretchCell prepare_stretch_cell(mesh::TriangleMesh mesh, const ContactSettings& contact);

// How the fluid mode started a force (stretch.fluid.warm_start): ramped with the warm start off;
// from the quasi-static equilibrium the warm start found; or ramped because the warm start did not
// converge or met a force law's limit on the way (a fallback, reported).
enum class WarmStart { off, converged, not_converged, force_law_limit };

struct StretchPoint {
  double force_pN = 0.0;
  double axial_um = 0.0;
  double transverse_um = 0.0;
  bool converged = false;
  // Relaxation iterations at this force: quasi-static, or the fluid mode's warm start.
  std::size_t iterations = 0;
  std::size_t steps = 0;       // coupled time steps (fluid) at this force
  double time_s = 0.0;         // simulated time spent at this force (fluid)
  // The largest vertex speed at this force as a lattice Mach number u / c_s, and as a cell
  // Reynolds number u D / nu (D the axial diameter) (fluid).
  double max_mach_number = 0.0;
  double max_reynolds_number = 0.0;
  double residual_force_pN = 0.0;  // largest net vertex force at the end
  std::size_t force_cap_hits = 0;  // vertex force cap triggers while relaxing (a safety net)
  double wall_time_s = 0.0;
  WarmStart warm_start = WarmStart::off;  // fluid mode
};

// What an observer sees after each force: the point, the shape reached, the membrane forces
// there (per term, for output; null when a force law reached its limit at this shape, so there
// are none) and the tweezer forces.
struct StretchState {
  std::size_t point_index;  // in StretchRun::points (a resumed fluid run starts past 0)
  const StretchPoint& point;
  std::span<const Vec3> positions_um;
  const membrane::MembraneForces* membrane_forces;
  std::span<const Vec3> external_forces_pN;
};
using StretchObserver = std::function<void(const StretchState&)>;

struct StretchRun {
  std::vector<StretchPoint> points;  // one per force reached, the failed one included
  std::string failure;               // empty when every force converged; else why the run stopped
  bool interrupted = false;          // by a signal (failure says which), between two points
  coupling::SubSpacingDragSummary sub_spacing_drag;  // the fluid mode's (quasi-static: off)
  bool ok() const { return failure.empty(); }
};

std::vector<std::string> stretch_mode_names();

// Runs settings.forces_pN in order. A force that does not converge, a force cap that holds at
// equilibrium, or a force law reaching its limit stops the run: the point is recorded (and
// observed, so its shape can be inspected) and StretchRun::failure says why; nothing is
// silently accepted. An interrupt (common/interrupt.hpp) stops it likewise, with the points
// reached so far. Throws InputError for an unknown mode or relaxation name.
StretchRun run_stretch(const membrane::MembraneModel& model, const StretchCell& cell,
                       const StretchSettings& settings, const StretchObserver& observer);

}  // namespace rbcsim::cases
