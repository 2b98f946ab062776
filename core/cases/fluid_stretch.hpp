// The "fluid" stretch mode (DESIGN.md §4 "stretch", paper §3.1): the cell in a periodic box of
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
