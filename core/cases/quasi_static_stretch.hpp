// The "quasi-static" stretch mode: no fluid. For each force the membrane is relaxed to
// equilibrium under the tweezer forces, starting from the previous force's shape (continuation:
// the shape changes little between neighbouring forces, so each relaxation starts close to its
// answer). Converged when the largest net vertex force (membrane + tweezers, the total-curvature
// kinks smoothed: curvature_kinks.hpp) is below relaxation_settings.force_tolerance_pN; then on
// every patch the membrane forces sum to -F (up to that smoothing on edges around the patch).
#pragma once

#include "cases/stretch_case.hpp"

namespace rbcsim::cases {

StretchRun run_quasi_static_stretch(const membrane::MembraneModel& model, const StretchCell& cell,
                                    const StretchSettings& settings,
                                    const StretchObserver& observer);

}  // namespace rbcsim::cases
