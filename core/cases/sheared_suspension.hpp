// Many cells in a wall-bounded simple shear flow (docs/physics.md, "Sheared suspensions"): the
// Couette viscometer of blood rheology, at one shear rate.
//
//   1. the cells packed to the target hematocrit into the gap between two flat walls
//      (suspension_packing.hpp, PackingSlab), periodic along the flow (x) and the vorticity (z);
//   2. the walls at y = -gap/2 and +gap/2 slide at -/+ rate * gap / 2 (the shear case's "walls"
//      boundary, shear_case.hpp); the fluid starts with the linear profile;
//   3. the cells are pushed off the walls (wall_repulsion.hpp) and off each other
//      (contact/cell_repulsion.hpp) for `strain` units of rate x time.
//
// Measured every sample: the shear stress the walls must carry, over the plasma's alone at the
// same rate, the relative viscosity. In a steady wall-bounded shear flow the plane-averaged
// momentum balance gives the wall stress as the volume average of the fluid's viscous stress plus
// the first moment of the forces the cells put into the fluid (Batchelor 1970, J Fluid Mech
// 41:545, eq. 4.11, in its form for point forces):
//     tau = mu gamma + mu_delta + sigma_p,
//     sigma_p  = -(1/V) sum_i y_i F_x,i     (every vertex force spread into the fluid, the membrane
//                                            viscosity's friction included),
//     mu_delta = (1/V) sum over the inner-fluid nodes of (mu(x) - mu) (du_x/dy + du_y/dx) dV
//                                           (the cytoplasm's extra viscous stress),
// with V the gap's volume and y measured from mid-gap (the forces sum to zero, so the origin
// does not matter). The relative viscosity is tau / (mu gamma), averaged over the samples of the
// last `averaging_fraction` of the run. As a check where no cell reaches the walls, the same ratio
// from the plane-averaged velocity gradient between the two fluid layers next to each wall
// (exact there: no force acts between them and the wall).
//
// Checkpoints: the samples taken so far ride in the simulation's checkpoint (a stop criterion's
// state), so a run resumed through `configure` (CoupledSimulation::resume_from) ends with the
// straight run's samples bit for bit.
#pragma once

#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "cases/suspension_case.hpp"
#include "cases/suspension_packing.hpp"
#include "contact/cell_repulsion.hpp"
#include "coupling/coupled_simulation.hpp"

namespace rbcsim::cases {

struct ShearedSuspensionSettings {
  double gap_um = 0.0;            // between the walls, rounded to whole lattice spacings
  double length_um = 0.0;         // periodic along x (the flow), rounded to whole spacings
  double width_um = 0.0;          // periodic along z (the vorticity), rounded to whole spacings
  double shear_rate_per_s = 0.0;  // as simulated
  double strain = 10.0;           // run length, rate x time
  double sample_interval_strain = 0.1;
  double averaging_fraction = 0.5;  // of the run, at its end
  double wall_repulsion_pN_per_um2 = 20.0;
  double wall_repulsion_range_um = 0.5;
  WallLaw wall_law = WallLaw::pressure;  // suspension.wall_law (wall_repulsion.hpp)
  contact::ContactParameters contact{5.0, 1.0, contact::ContactLaw::surface, 50.0};
  PackingSettings packing;
  double growth_time_s = 0.005;        // of cells packed below their size (SuspensionSettings)
  std::vector<CellPose> placed_cells;  // instead of the packing (y = 0 at mid-gap)
};

struct ShearedSuspensionSample {
  double time_s = 0.0;
  double strain = 0.0;
  double relative_viscosity = 0.0;
  double particle_stress_Pa = 0.0;            // sigma_p
  double cytoplasm_stress_Pa = 0.0;           // mu_delta
  double near_wall_relative_viscosity = 0.0;  // the check
  std::size_t contact_pairs = 0;
  std::size_t pierced_cells = 0;
};

struct ShearedSuspensionCellSample {
  double time_s = 0.0;
  std::size_t cell = 0;
  Vec3 centroid_um = Vec3::Zero();  // y = 0 at mid-gap
  double deformation_index = 0.0;
};

struct ShearedSuspensionRun {
  std::vector<std::size_t> cell_morphologies;
  double gap_um = 0.0, length_um = 0.0, width_um = 0.0;  // as rounded to the lattice
  double packed_hematocrit = 0.0;
  std::size_t packing_iterations = 0;
  double plasma_stress_Pa = 0.0;  // mu gamma
  std::vector<ShearedSuspensionSample> samples;
  std::vector<ShearedSuspensionCellSample> cell_samples;
  std::size_t averaged_samples = 0;
  double relative_viscosity = 0.0;
  double relative_viscosity_sd = 0.0;
  double near_wall_relative_viscosity = 0.0;
  std::size_t steps = 0;
  double time_s = 0.0;
  std::size_t close_contact_steps = 0;
  std::size_t capped_contact_steps = 0;
  std::size_t samples_with_pierced_cells = 0;
  coupling::SubSpacingDragSummary sub_spacing_drag;
  std::string stop_reason;
  std::string failure;
  bool interrupted = false;
  bool ok() const { return failure.empty(); }
};

// Throws InputError for bad settings (naming the suspension.* or shear.* key), cells that cannot
// be packed, or wall speeds beyond the lattice's Mach limit; runtime failures end the run with
// ShearedSuspensionRun::failure set.
ShearedSuspensionRun run_sheared_suspension(std::span<const SuspensionMorphology> morphologies,
                                            std::span<const std::size_t> cell_morphologies,
                                            const SuspensionPhysics& physics,
                                            const ShearedSuspensionSettings& settings,
                                            const SuspensionConfigure& configure = {});

// The whole run as JSON and back, every number as run (doubles round-trip exactly): what `shear`
// keeps of a finished rate so that --resume need not run it again. The reader throws InputError
// naming `source` for a record it cannot read.
nlohmann::ordered_json sheared_suspension_record(const ShearedSuspensionRun& run);
ShearedSuspensionRun sheared_suspension_from_record(const nlohmann::json& record,
                                                    const std::string& source);

// The shear stress the cells add to the plasma's in the gap (the header's sigma_p and mu_delta),
// Pa, from the simulation's latest step; `gap_nodes` fluid layers between the walls.
struct SuspensionShearStress {
  double particle_Pa = 0.0;
  double cytoplasm_Pa = 0.0;
};
SuspensionShearStress suspension_shear_stress(const coupling::CoupledSimulation& simulation,
                                              int gap_nodes);

}  // namespace rbcsim::cases
