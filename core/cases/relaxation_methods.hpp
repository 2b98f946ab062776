// The membrane-only relaxations a quasi-static case can use, by name (one table,
// relaxation_methods.cpp):
//   "fire"   fire_relaxation.hpp: an accelerated minimiser with the total-curvature kinks
//            smoothed; the default.
//   "euler"  membrane/relaxation.hpp: the membrane module's overdamped explicit Euler, for
//            comparison on smooth energies (tested to find FIRE's equilibrium there). It takes
//            the model's forces as they are, so with total_curvature enabled its net force keeps
//            the kink jumps and it reports non-convergence.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/relaxation.hpp"

namespace rbcsim::cases {

using RelaxationMethod = membrane::RelaxationResult (*)(const membrane::MembraneModel& model,
                                                        std::span<Vec3> positions_um,
                                                        std::span<const Vec3> external_forces_pN,
                                                        const membrane::RelaxationSettings&);

std::vector<std::string> relaxation_method_names();

// Throws InputError("stretch.quasi_static.relaxation", ...) for an unknown name.
RelaxationMethod find_relaxation_method(std::string_view name);

}  // namespace rbcsim::cases
