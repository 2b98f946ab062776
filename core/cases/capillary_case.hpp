// One cell through a stenosed capillary (paper §3.3-3.4; docs/physics.md):
//
//   1. the fluid alone (capillary_flow.hpp) run from rest to its steady state;
//   2. the cell released at rest on the tube axis, its upstream end release_gap_um downstream of
//      the inlet plane, the mesh's z axis (the built-in shapes' symmetry axis) turned onto
//      `cell_axis` (default z: the disc in the x-y plane, DI = 1 for a discocyte);
//   3. the coupled run (core/coupling), with the wall's short-range repulsion (wall_repulsion.hpp)
//      as an external force, until the centroid is pass_margin_um beyond the narrow
//      section (passed), the cell's downstream end is within kOutletGuardDx lattice spacings of
//      the outlet, or max_time_s. Reaching the guard or the time limit before the centroid left
//      the narrow section is a failure (not passed), never silent.
//
// Recorded: every sample_interval_s a CapillarySample; every step the transit through the narrow
// section (capillary_observables.hpp: entry and exit times of the centroid, interpolated) and the
// peak deformation index with where it occurred.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cases/capillary_observables.hpp"
#include "cases/wall_repulsion.hpp"
#include "common/vec3.hpp"
#include "coupling/coupled_simulation.hpp"
#include "geometry/wall_shape.hpp"
#include "membrane/parameters.hpp"
#include "mesh/geometry.hpp"
#include "mesh/triangle_mesh.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::cases {

// The run stops before the cell's downstream end comes this close (in dx) to the outlet plane:
// the immersed boundary's stencil must not reach the outlet layer.
inline constexpr double kOutletGuardDx = 2.0;

struct CapillarySettings {
  double mean_inlet_velocity_m_per_s = 0.0;  // over the inlet section; > 0
  std::string cell_axis = "z";               // a name of cell_axis_names()
  double release_gap_um = 1.0;
  // The wall's push on the membrane (wall_repulsion.hpp), as a pressure at contact: each vertex
  // gets it times its share of the membrane area. Built-in (circular) capillaries only; 0: none.
  double wall_repulsion_pN_per_um2 = 20.0;
  double wall_repulsion_range_um = 0.5;
  double pass_margin_um = 4.0;
  double max_time_s = 0.05;  // > 0; the config's 0 (the default) is resolved in setup/
  double sample_interval_s = 1e-5;
  // The fluid alone is steady when max |u(t) - u(t - check)| <= tolerance * max |u| over
  // `fluid_check_interval_steps`, within fluid_max_steps (else the run fails).
  double fluid_tolerance = 1e-6;
  std::size_t fluid_check_interval_steps = 100;
  std::size_t fluid_max_steps = 200000;
};

std::vector<std::string> cell_axis_names();

// Everything the case needs besides the settings: the physics, already resolved.
struct CapillaryPhysics {
  const geometry::WallShape& wall;
  std::string wall_source;  // for diagnostics ("capillary.geometry", the STL file)
  membrane::MembraneParameters membrane;
  lattice::FluidParameters fluid;
  coupling::CouplingParameters coupling;
  units::UnitConverter units;
  double density_kg_per_m3 = 0.0;
  double kinematic_viscosity_m2_per_s = 0.0;
  double thermal_energy_J = 0.0;
};

struct CapillarySample {
  double time_s = 0.0;
  Vec3 centroid_um = Vec3::Zero();
  double velocity_x_m_per_s = 0.0;
  double deformation_index = 0.0;
  Vec3 extents_um = Vec3::Zero();
  mesh::AreaStrain area_strain;
};

struct CapillaryFlowNumbers {
  double mean_inlet_velocity_m_per_s = 0.0;
  double inlet_diameter_um = 0.0;
  double reynolds_number = 0.0;
  double shear_modulus_N_per_m = 0.0;  // of the link term at the mesh's mean edge length
  double capillary_number = 0.0;
};

struct CapillaryRun {
  CapillaryFlowNumbers numbers;
  double narrow_start_um = 0.0;
  double narrow_end_um = 0.0;
  std::size_t fluid_settling_steps = 0;
  std::vector<CapillarySample> samples;
  std::optional<double> entry_time_s;  // of the centroid (the paper's transit)
  std::optional<double> exit_time_s;
  std::optional<double> transit_time_s;
  // The whole cell's transit, independent of the centroid: from its first vertex entering the
  // narrow section (its front, the largest x, reaching the start) to its last vertex leaving it
  // (its rear, the smallest x, passing the end).
  std::optional<double> front_entry_time_s;
  std::optional<double> rear_exit_time_s;
  std::optional<double> whole_cell_transit_time_s;
  // Confinement: the stress-free cell's largest extent over the throat's diameter.
  double cell_diameter_um = 0.0;
  double throat_diameter_um = 0.0;
  double confinement() const { return cell_diameter_um / throat_diameter_um; }
  bool passed = false;
  double initial_deformation_index = 0.0;
  double peak_deformation_index = 0.0;
  double peak_time_s = 0.0;
  double peak_centroid_x_um = 0.0;
  double final_deformation_index = 0.0;
  double final_centroid_x_um = 0.0;
  std::size_t steps = 0;
  double time_s = 0.0;
  std::string stop_reason;
  std::size_t force_capped_steps = 0;
  // Where this process's coupled steps spent their time (after a resume: the resumed part).
  coupling::StepPhaseTimes phase_times;
  coupling::SubSpacingDragSummary sub_spacing_drag;
  std::string failure;       // empty when the cell passed; else why not
  bool interrupted = false;  // Ctrl-C: the record so far, a checkpoint written if wired
  bool ok() const { return failure.empty(); }
};

// Called once the simulation holds the settled fluid and the cell, before it runs (VTK output).
using CapillaryConfigure = std::function<void(coupling::CoupledSimulation&)>;

// The mesh is the stress-free cell, anywhere (it is oriented and placed here). Throws InputError
// for bad settings, a wall that is not a lumen along x, a velocity beyond the lattice's Mach
// limit, or a cell that does not fit in the inlet section. Runtime failures (the fluid not
// settling, an instability of the coupled run) end the run with CapillaryRun::failure set.
CapillaryRun run_capillary(const mesh::TriangleMesh& cell_mesh, const CapillaryPhysics& physics,
                           const CapillarySettings& settings,
                           const CapillaryConfigure& configure = {});

// The cell mesh turned so that its z axis lies along `cell_axis` (a rigid rotation about the
// origin). Throws InputError naming capillary.cell_axis for an unknown axis.
mesh::TriangleMesh oriented_cell(mesh::TriangleMesh mesh, std::string_view cell_axis);

}  // namespace rbcsim::cases
