#include "cases/sheared_suspension.hpp"
#include "cases/suspension_case.hpp"
#include "config/options/option_areas.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the case's settings struct: one source of truth.
const cases::SuspensionSettings kSuspensionDefaults{};
const cases::ShearedSuspensionSettings kShearedDefaults{};

}  // namespace

void add_suspension_options(OptionTable& table) {
  table
      .add_number("suspension.hematocrit", "", 0.0,
                  "Hematocrit the cells are packed to (cell volume over the space's volume): the "
                  "tube's in `capillary --geometry tube`, the gap's in `shear --hematocrit`; 0: "
                  "no suspension.")
      .at_least(0.0)
      .at_most(0.7);
  table.add_cell_list(
      "suspension.cells", morphology_choices(),
      "Cells placed by hand instead of packed to suspension.hematocrit: each a morphology, its "
      "centroid (centre_um: the tube's axis along x at y = z = 0; in shear, y = 0 at mid-gap, "
      "x and z from 0 to the box's length and width), its symmetry axis and a spin.");
  table.add_string("suspension.mix", "",
                   "Morphologies of the suspension's cells, as number fractions summing to 1: "
                   "discocyte=0.8,echinocyte-III=0.2. Empty: all of the configured morphology.");
  table.add_number("suspension.tube_diameter_um", "um", 20.0, "Diameter of the straight tube.")
      .above(0.0);
  table
      .add_number("suspension.tube_length_um", "um", 40.0,
                  "Length of the tube, periodic along its axis (x).")
      .above(0.0);
  table
      .add_number("suspension.plasma_mean_velocity_m_per_s", "m/s", 2e-3,
                  "Drive: the body force (pressure gradient) that would move plasma alone through "
                  "the tube at this mean velocity (the default is a pseudo-shear rate U/D of "
                  "100 1/s in the 20 um tube, within Pries et al. 1992's high-shear data).")
      .above(0.0);
  table
      .add_number("suspension.duration_s", "s", 0.02,
                  "Simulated (physical) time of the coupled run after the plasma has settled.")
      .above(0.0);
  table
      .add_number("suspension.sample_interval_s", "s", 2e-4,
                  "Interval of the whole-flow and per-cell samples.")
      .above(0.0);
  table
      .add_number("suspension.strain", "", kShearedDefaults.strain,
                  "`shear --hematocrit`: how long each rate runs, in strain (rate x time).")
      .above(0.0);
  table
      .add_number("suspension.sample_interval_strain", "", kShearedDefaults.sample_interval_strain,
                  "`shear --hematocrit`: interval of the stress and per-cell samples, in strain.")
      .above(0.0);
  table
      .add_number("suspension.averaging_fraction", "", kSuspensionDefaults.averaging_fraction,
                  "The reported averages are over this last fraction of the run.")
      .above(0.0)
      .at_most(1.0);
  table
      .add_integer("suspension.profile_rings", "",
                   static_cast<int>(kSuspensionDefaults.profile_rings),
                   "Rings of equal width about the tube's axis over which the hematocrit profile "
                   "(the cells' volume fraction) is measured.")
      .at_least(1)
      .at_most(25);
  table
      .add_number("suspension.contact_force_pN", "pN",
                  kSuspensionDefaults.contact.force_at_contact_pN,
                  "Strength of the cell-cell repulsion: the surface law's push at half the range, "
                  "the vertex law's pair force at zero distance (contact_law).")
      .at_least(0.0);
  table.add_choice("suspension.contact_law", contact::contact_law_names(),
                   contact::contact_law_name(kSuspensionDefaults.contact.law),
                   "How cells push each other apart: vertex (vertex pairs, F0 (1 - d/r)^2, "
                   "contact_force_pN at d = 0) or surface (each vertex from the nearest point of "
                   "another cell's surface, F (r/d - 1)^2, contact_force_pN at d = r/2).");
  table
      .add_number("suspension.contact_force_cap_pN", "pN", kSuspensionDefaults.contact.force_cap_pN,
                  "Surface law: the largest push a vertex gets from one other cell; closer in, "
                  "the push stays at the cap (its steps are counted as capped_contact_steps). "
                  "The default is membrane.vertex_force_cap_pN's.")
      .above(0.0);
  table
      .add_number("suspension.contact_range_um", "um", kSuspensionDefaults.contact.range_um,
                  "Range of the cell-cell repulsion; at least the membranes' longest edge, and "
                  "best the immersed-boundary kernel's width (2 lattice spacings for phi2) or "
                  "more: closer membranes are not parted by the fluid (a notice says so).")
      .above(0.0);
  table
      .add_number("suspension.wall_repulsion_pN_per_um2", "pN/um^2",
                  kSuspensionDefaults.wall_repulsion_pN_per_um2,
                  "The tube wall's push on the membrane at contact, as a pressure (as "
                  "capillary.wall_repulsion_pN_per_um2).")
      .at_least(0.0);
  table.add_choice("suspension.wall_law", cases::wall_law_names(),
                   cases::wall_law_name(kSuspensionDefaults.wall_law),
                   "The wall's force law: pressure (wall_repulsion_pN_per_um2 (1 - d/r)^2 over "
                   "a vertex's share of the area, finite at contact) or barrier (the cells' "
                   "surface contact law against the wall: a quarter of that (r/d - 1)^2, the "
                   "same at d = r/2, growing without a cap closer in, so that a cell squeezed "
                   "between neighbours cannot be pushed through the wall; docs/physics.md).");
  table
      .add_number("suspension.wall_repulsion_range_um", "um",
                  kSuspensionDefaults.wall_repulsion_range_um,
                  "Distance from the wall within which its repulsion acts.")
      .above(0.0);
  table.add_integer("suspension.seed", "", 1, "Seed of the packing's random places and turns.")
      .at_least(0);
  table.add_choice("suspension.packing_orientation", {"random", "axial"}, "random",
                   "How the packed cells start: random (uniformly random places and "
                   "orientations) or axial (symmetry axes along the tube, evenly spaced along it "
                   "in random order), for tubes too narrow for randomly turned cells to pack.");
  table
      .add_integer("suspension.packing_max_iterations", "",
                   static_cast<int>(kSuspensionDefaults.packing.max_iterations),
                   "Packing gives up (exit 2, with the hematocrit it reached) after this many "
                   "push-apart iterations.")
      .at_least(1);
  table
      .add_number("suspension.packing_scale", "", kSuspensionDefaults.packing.scale,
                  "The size the cells are packed at, a fraction of their own: below 1 they grow "
                  "to full size in the flow over suspension.growth_time_s (each cell scaled about "
                  "its centroid every step, its membrane's reference in stages of 0.1 %), for "
                  "hematocrits a packing of cells at their resting shape cannot reach. The "
                  "hematocrit reported is the grown cells'.")
      .at_least(0.5)
      .at_most(1.0);
  table
      .add_number("suspension.growth_time_s", "s", kSuspensionDefaults.growth_time_s,
                  "With suspension.packing_scale below 1: the physical time from the release over "
                  "which the cells grow to full size; it must end before the averaging window "
                  "starts, and last several of a cell's relaxation times (about 1 ms in plasma), "
                  "so that the walls and the other cells can turn and shape the growing cells.")
      .above(0.0);
  table
      .add_number("suspension.max_reynolds_number", "", 0.1,
                  "Time-scale compression (as capillary.time_scale_compression): plasma viscosity "
                  "divided and velocity multiplied by one factor, at equal capillary number, up to "
                  "this Reynolds number (U D / nu); times are reported physical.")
      .above(0.0);
}

}  // namespace rbcsim::config
