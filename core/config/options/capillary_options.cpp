#include "cases/capillary_case.hpp"
#include "common/registry.hpp"
#include "config/options/option_areas.hpp"
#include "geometry/capillary_wall.hpp"
#include "geometry/wall_registry.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the case's settings struct: one source of truth.
const cases::CapillarySettings kCapillaryDefaults{};

void add_wall_options(OptionTable& table) {
  // The validation case by default: it is the paper's discocyte experiment (§3.3, Fig. 13), and
  // the discocyte is the default morphology.
  auto geometries = geometry::paper_capillary_names();
  geometries.emplace_back("tube");
  table.add_choice("capillary.geometry", geometries, "paper-validation",
                   "Built-in capillary: the paper's validation case (31.2 um long, 10.2 um across, "
                   "6.75 um throat) or its three-morphology case (42 um, 10 um, 6.8 um); tube: "
                   "the straight periodic tube of a suspension (suspension.*).");
  table.add_string("capillary.wall_file", "",
                   "Wall surface (STL, fluid inside, lumen open along x) used instead of the "
                   "built-in capillary; empty: the built-in one.");
  table.add_choice("capillary.profile", entry_names(geometry::narrowing_profiles()), "cosine",
                   "Shape of the constriction of the built-in capillary (the paper gives none).");
  table
      .add_number("capillary.throat_diameter_um", "um", 0.0,
                  "Throat diameter of the built-in capillary; 0: the paper's for the geometry.")
      .at_least(0.0);
  table
      .add_number("capillary.constriction_length_um", "um", 0.0,
                  "Length of the constriction of the built-in capillary, centred; 0: a third of "
                  "the tube.")
      .at_least(0.0);
}

void add_flow_options(OptionTable& table) {
  table
      .add_number("capillary.inlet_velocity_m_per_s", "m/s",
                  kCapillaryDefaults.mean_inlet_velocity_m_per_s,
                  "Mean velocity over the inlet (Poiseuille profile); 0: the velocity giving the "
                  "paper's Reynolds number for the geometry (0.0643 validation, 0.04 "
                  "three-morphology) with physics.plasma_kinematic_viscosity_m2_per_s.")
      .at_least(0.0);
  table
      .add_number("capillary.fluid_tolerance", "", kCapillaryDefaults.fluid_tolerance,
                  "The fluid alone is steady when its largest velocity change per check interval "
                  "is below this fraction of its largest velocity.")
      .above(0.0);
  table
      .add_integer("capillary.fluid_max_steps", "",
                   static_cast<int>(kCapillaryDefaults.fluid_max_steps),
                   "Steps allowed for the fluid alone to become steady; more fails the run.")
      .at_least(1);
}

void add_cell_options(OptionTable& table) {
  table.add_choice("capillary.cell_axis", cases::cell_axis_names(), kCapillaryDefaults.cell_axis,
                   "Lab axis the cell mesh's z axis (a built-in shape's symmetry axis) is turned "
                   "onto; z: a discocyte's disc lies in the x-y plane (DI = 1 at release).");
  table
      .add_number("capillary.release_gap_um", "um", kCapillaryDefaults.release_gap_um,
                  "Gap between the inlet plane and the cell's upstream end at release.")
      .above(0.0);
  table
      .add_number("capillary.wall_repulsion_pN_per_um2", "pN/um^2",
                  kCapillaryDefaults.wall_repulsion_pN_per_um2,
                  "Wall push on the membrane at contact, per membrane area (it stands in for the "
                  "lubrication film the lattice cannot resolve); 0: none. Built-in capillaries "
                  "only.")
      .at_least(0.0);
  table
      .add_number("capillary.wall_repulsion_range_um", "um",
                  kCapillaryDefaults.wall_repulsion_range_um,
                  "Distance from the wall within which the repulsion acts.")
      .above(0.0);
  table
      .add_number("capillary.pass_margin_um", "um", kCapillaryDefaults.pass_margin_um,
                  "The cell has passed once its centroid is this far beyond the narrow section.")
      .above(0.0);
  table
      .add_number("capillary.max_time_s", "s", 0.0,
                  "Simulated time allowed after release; a cell that has not passed by then "
                  "fails the run. 0: the time the mean inlet flow takes to cross the tube "
                  "(a passing cell needs about a third of it).")
      .at_least(0.0);
  table
      .add_number("capillary.sample_interval_s", "s", kCapillaryDefaults.sample_interval_s,
                  "Time between rows of capillary_timeseries.csv.")
      .above(0.0);
}

void add_ensemble_options(OptionTable& table) {
  table
      .add_integer("capillary.orientations", "", 1,
                   "Releases of the cell in as many orientations (cases/release_orientations.hpp: "
                   "a Fibonacci set on the sphere, the first the configured one, each spun by a "
                   "seeded angle); with more than one, the run reports the transit's mean and "
                   "spread (result.json capillary_ensemble) and keeps each in orientation_<k>/.")
      .at_least(1)
      .at_most(1000);
  table.add_integer("capillary.orientation_seed", "", 1, "Seed of the orientations' spins.")
      .at_least(0);
}

void add_compression_options(OptionTable& table) {
  table.add_boolean("capillary.time_scale_compression", true,
                    "Simulate the flow faster with a proportionally lower viscosity (the same "
                    "capillary number, so the same shapes and transit) up to "
                    "capillary.max_reynolds_number; results are converted back to physical time.");
  table
      .add_number("capillary.max_reynolds_number", "", 0.02,
                  "Largest Reynolds number U D_inlet / nu the compression may reach: Stokes flow "
                  "needs << 1, and the explicit membrane step moves s^2 further per step "
                  "(docs/physics.md, time-scale compression).")
      .above(0.0);
}

}  // namespace

void add_capillary_options(OptionTable& table) {
  add_wall_options(table);
  add_flow_options(table);
  add_cell_options(table);
  add_compression_options(table);
  add_ensemble_options(table);
}

}  // namespace rbcsim::config
