// The suspension experiment (`rbcsim capillary --geometry tube --hematocrit H`) from a config: its
// settings, its morphologies (each with its own overlay: mesh and Table 2 stiffnesses), the
// number of cells of each, and its low-Reynolds time-scale compression.
#pragma once

#include <string>
#include <vector>

#include "cases/suspension_case.hpp"
#include "config/config.hpp"

namespace rbcsim::setup {

// suspension.mix parsed: names (morphologies, in the order given) and number fractions. Empty
// mix: the configured morphology alone. Throws InputError naming suspension.mix for an unknown
// morphology, a repeated one, a fraction outside (0, 1] or fractions not summing to 1 (within
// 1e-6).
struct SuspensionMix {
  std::vector<std::string> names;
  std::vector<double> fractions;
};
SuspensionMix suspension_mix_from(const config::Config& config);

cases::SuspensionSettings suspension_settings_from(const config::Config& config);

// Each morphology of the mix resolved from `request` with its own --morphology: mesh and membrane.
std::vector<cases::SuspensionMorphology> suspension_morphologies_from(
    const config::ConfigRequest& request, const SuspensionMix& mix, double compression_factor);

// As the capillary's (capillary_from_config.hpp): below suspension.max_reynolds_number the run
// divides the plasma viscosity (and the membrane's) by s and multiplies the drive velocity by s,
// at equal capillary number; every time is divided by s, to be multiplied back in the results.
struct SuspensionCompression {
  double factor = 1.0;
  double physical_reynolds_number = 0.0;
  double simulated_reynolds_number = 0.0;
};
SuspensionCompression suspension_compression_from(const config::Config& config);
config::Config compressed_suspension_config(const config::Config& config, double factor);
// Times back to physical ones (x s), velocities and flow rates (/ s), the gradient (/ s^2 x s).
void to_physical_units(cases::SuspensionRun& run, double factor);

}  // namespace rbcsim::setup
