// calibrate.* options -> cases::CalibrationSettings.
#pragma once

#include "cases/calibration.hpp"
#include "config/config.hpp"

namespace rbcsim::setup {

cases::CalibrationSettings calibration_settings_from(const config::Config& config);

}  // namespace rbcsim::setup
