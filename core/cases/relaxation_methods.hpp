// The membrane-only relaxations a quasi-static case can use, by name (one table,
// relaxation_methods.cpp): "fire" (fire_relaxation.hpp, an accelerated minimiser, the default)
// and "euler" (membrane/relaxation.hpp, overdamped explicit Euler: a physical trajectory, but
// thousands of steps). Both stop at the same criterion, so they find the same equilibrium.
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
