// `rbcsim capillary --geometry tube --hematocrit H [--mix ...]`: many cells in a straight periodic
// tube (core/cases/suspension_case.hpp), the capillary command's second experiment.
#pragma once

#include "common_options.hpp"
#include "config/config.hpp"

namespace rbcsim::cli {

// Whether the config asks for the suspension (capillary.geometry tube, or a hematocrit). Throws
// InputError when it asks for half of it: a tube without a hematocrit, or a hematocrit in one of
// the paper's capillaries.
bool wants_suspension(const config::Config& config);

// Runs it; `request` is the one `config` was resolved from (each morphology of the mix is
// resolved from it with its own overlay).
void run_suspension_command(const config::ConfigRequest& request, const config::Config& config,
                            const CommonOptions& common, const CheckpointOptions& checkpoint);

}  // namespace rbcsim::cli
