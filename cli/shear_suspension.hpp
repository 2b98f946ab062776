// `rbcsim shear --hematocrit H [--mix ...]`: many cells sheared between two sliding walls
// (core/cases/sheared_suspension.hpp), the shear command's second experiment: the relative
// viscosity of the suspension at each rate.
#pragma once

#include "common_options.hpp"
#include "config/config.hpp"

namespace rbcsim::cli {

// Whether the config asks for a sheared suspension (suspension.hematocrit > 0 or
// suspension.cells). Throws InputError for both at once, or for a boundary other than walls.
bool wants_sheared_suspension(const config::Config& config);

// Runs it; `request` is the one `config` was resolved from (each morphology of the mix is
// resolved from it with its own overlay).
void run_sheared_suspension_command(const config::ConfigRequest& request,
                                    const config::Config& config, const CommonOptions& common,
                                    const CheckpointOptions& checkpoint);

}  // namespace rbcsim::cli
