// membrane.* options -> membrane::MembraneParameters (in the membrane module's pN / um units).
#pragma once

#include "config/config.hpp"
#include "membrane/parameters.hpp"

namespace rbcsim::setup {

membrane::MembraneParameters membrane_parameters_from(const config::Config& config);

}  // namespace rbcsim::setup
