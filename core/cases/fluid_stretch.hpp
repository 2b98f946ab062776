// The "fluid" stretch mode (paper §3.1; docs/physics.md): the cell in a periodic box of
// fluid at rest, the tweezer forces a coupling::ExternalForce, each force run until the axial
// and transverse diameters are both steady (coupling::stop_at_steady_state) or until
// max_time_per_force_s. The forces are applied in order to one simulation, each continuing from
// the previous force's state (shape and flow), so the whole curve is one run.
//
// At a steady state the vertices no longer move, so the membrane force balances the tweezers at
// every vertex the fluid can resolve: the equilibrium of the quasi-static mode, reached through
// the fluid's dissipation instead of an optimiser's.
//
// A point that does not become steady within its time is recorded (converged: false) and the run
// goes on to the next force, the failure naming every such force; an instability (coupling's
// stability checks) stops the run there, its point recorded.
//
// Checkpoints (docs/architecture.md): settings.fluid.configure gets the simulation before the first
// force (a policy, a resume). The curve's progress rides in the simulation's checkpoint as a stop
// criterion that never stops: the force being applied, its ramp and start record (step, force-cap
// count, largest speed, wall time so far), the points measured before it; the force's stop
// criterion carries its deadline and steady-state checks. A resumed run continues that force at
// the checkpoint's step and ends with the straight run's points, bit for bit (checkpoints after an
// even number of fluid steps; docs/architecture.md, "Reliability"). An interrupt
// (common/interrupt.hpp) ends the run with StretchRun::interrupted and the points of the forces
// done; the unfinished force is not a point.
#pragma once

#include <array>
#include <span>

#include "cases/stretch_case.hpp"

namespace rbcsim::cases {

StretchRun run_fluid_stretch(const membrane::MembraneModel& model, const StretchCell& cell,
                             const StretchSettings& settings, const StretchObserver& observer);

// The periodic box around the resting cell: node counts and where node (0, 0, 0) sits (um).
struct StretchBox {
  std::array<int, 3> nodes{};
  Vec3 origin_um = Vec3::Zero();
};
StretchBox stretch_box(std::span<const Vec3> positions_um, double dx_um, double margin_um);

}  // namespace rbcsim::cases
