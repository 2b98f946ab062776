// The stiffest mode of a force field: lambda_max of its Jacobian, by power iteration on finite
// differences of the force. Explicit and inertial steps are stable below a limit set by it, so
// every minimiser of rbcsim sets its step from this estimate; it covers any force law (the
// membrane's singular tau terms at the current deformation, forces that are not a gradient)
// without a per-term formula.
#pragma once

#include <functional>
#include <span>

#include "common/vec3.hpp"

namespace rbcsim::minimise {

// Writes the force at `positions` into `forces` (same length).
using ForceField = std::function<void(std::span<const Vec3> positions, std::span<Vec3> forces)>;

// lambda_max (force per length, in the field's units) at `positions`: 30 power iterations from a
// fixed pseudo-random direction (reproducible), probing with a displacement of
// probe_length / max |direction| so the largest point moves probe_length (small enough to stay
// linear, large enough against round-off; the membrane uses 1e-6 of its mean edge).
double estimate_stiffest_mode(const ForceField& forces, std::span<const Vec3> positions,
                              double probe_length);

}  // namespace rbcsim::minimise
