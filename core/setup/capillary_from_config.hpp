// capillary.* options (and the physics they need) -> the wall and the settings of the capillary
// case (core/cases/capillary_case.hpp).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "cases/capillary_case.hpp"
#include "config/config.hpp"
#include "geometry/wall_shape.hpp"

namespace rbcsim::setup {

// The paper's Reynolds numbers, which fix the default inlet velocity of its two capillaries:
// §3.3 "set to 0.0643 per reference (Gallage et al. 2014)", §3.4 "selected as 0.04".
inline constexpr double kPaperValidationReynoldsNumber = 0.0643;
inline constexpr double kPaperMorphologyReynoldsNumber = 0.04;

struct CapillaryWall {
  std::unique_ptr<geometry::WallShape> shape;
  std::string geometry;  // the preset's name, or the wall file
  std::string source;    // the option or file diagnostics name
};

// capillary.wall_file if given (an STL wall, open along x), else the built-in capillary
// capillary.geometry with capillary.profile and the non-zero capillary.throat_diameter_um and
// capillary.constriction_length_um. Throws InputError for an unreadable file or bad parameters.
CapillaryWall capillary_wall_from(const config::Config& config);

// The case's settings; a zero capillary.inlet_velocity_m_per_s becomes the velocity of the
// paper's Reynolds number for the built-in geometry, U = Re nu / D_inlet (InputError with a wall
// file: give the velocity).
cases::CapillarySettings capillary_settings_from(const config::Config& config,
                                                 const CapillaryWall& wall);

// Membrane, fluid, coupling and units; failure dumps go to run_directory.
cases::CapillaryPhysics capillary_physics_from(const config::Config& config,
                                               const CapillaryWall& wall,
                                               const std::filesystem::path& run_directory);

}  // namespace rbcsim::setup
