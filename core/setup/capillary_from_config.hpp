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

// Membrane (for a cell of this mesh: cell_membrane_parameters_from), fluid, coupling and units;
// failure dumps go to run_directory.
cases::CapillaryPhysics capillary_physics_from(const config::Config& config,
                                               const CapillaryWall& wall,
                                               const mesh::TriangleMesh& cell,
                                               const std::filesystem::path& run_directory);

// Low-Reynolds time-scale compression (docs/physics.md, "Time-scale compression"). In Stokes
// flow the cell's shapes and transit depend on the capillary number Ca = mu U / G_s, not on the
// Reynolds number: simulating U s with the viscosity divided by s keeps Ca, multiplies the
// Reynolds number by s^2 and, at the same relaxation time, dt by s, so a transit takes s^2 fewer
// steps. With capillary.time_scale_compression the factor is the largest s >= 1 that keeps
// Re = U D_inlet / nu at most capillary.max_reynolds_number; a wall file without a known inlet
// diameter, or the switch off, gives s = 1. Results are converted back (times x s, velocities
// / s) and result.json records s.
// The factor s of a low-Reynolds compression: sqrt(limit / Re) below the limit, else 1 (the
// simulated Reynolds number s^2 Re is then the limit). Shared by the capillary and the suspension.
double low_reynolds_compression_factor(double physical_reynolds_number,
                                       double max_reynolds_number);

struct CapillaryCompression {
  double factor = 1.0;                     // s
  double physical_reynolds_number = 0.0;   // U D_inlet / nu (0 when D_inlet is unknown)
  double simulated_reynolds_number = 0.0;  // s^2 times it
  double simulated_kinematic_viscosity_m2_per_s = 0.0;
  double simulated_inlet_velocity_m_per_s = 0.0;
};
CapillaryCompression capillary_compression_from(const config::Config& config,
                                                const CapillaryWall& wall);

// The configuration the compressed run simulates: physics.plasma_kinematic_viscosity_m2_per_s
// / s, capillary.inlet_velocity_m_per_s = the physical U times s, and capillary.max_time_s,
// capillary.sample_interval_s and the output.*_interval_s divided by s. The identity for s = 1.
config::Config compressed_capillary_config(const config::Config& config, const CapillaryWall& wall,
                                           const CapillaryCompression& compression);

// The run of the compressed configuration in physical units: every time x s, every velocity / s,
// the Reynolds number the physical one.
void to_physical_units(cases::CapillaryRun& run, const CapillaryCompression& compression);

}  // namespace rbcsim::setup
