#include "config/options/option_areas.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/import.hpp"
#include "shapes/energy_shape.hpp"
#include "shapes/named_cells.hpp"
#include "shapes/sequence.hpp"

namespace rbcsim::config {
namespace {

// Defaults come from the generators' parameter structs: one source of truth.
const mesh::CellShapeParameters kMeshDefaults{};

void add_discocyte_options(OptionTable& table) {
  const auto& shape = kMeshDefaults.discocyte;
  table.add_number("mesh.discocyte.radius_um", "um", shape.radius_um, "Evans-Fung radius R0.")
      .above(0.0);
  table.add_number("mesh.discocyte.c0", "", shape.c0, "Evans-Fung coefficient C0.");
  table.add_number("mesh.discocyte.c2", "", shape.c2, "Evans-Fung coefficient C2.");
  table.add_number("mesh.discocyte.c4", "", shape.c4, "Evans-Fung coefficient C4.");
}

void add_stomatocyte_options(OptionTable& table) {
  const auto& shape = kMeshDefaults.stomatocyte;
  table
      .add_number("mesh.stomatocyte.membrane_area_um2", "um^2", shape.membrane_area_um2,
                  "Membrane area (the discocyte's: area is conserved through the shape change).")
      .above(0.0);
  table
      .add_number("mesh.stomatocyte.reduced_volume", "", shape.reduced_volume,
                  "Reduced volume 6 sqrt(pi) V / A^1.5 the cup wall thickness is solved for.")
      .above(0.0)
      .below(1.0);
  table
      .add_number("mesh.stomatocyte.cup_half_angle_deg", "deg", shape.cup_half_angle_deg,
                  "Opening of the cup's midline arc (90 = hemisphere).")
      .above(0.0)
      .below(180.0);
  table
      .add_number("mesh.stomatocyte.rim_thickening", "", shape.rim_thickening,
                  "Wall half-thickness at the rim relative to the bottom, minus 1.")
      .at_least(0.0);
}

void add_echinocyte_options(OptionTable& table) {
  const auto& shape = kMeshDefaults.echinocyte;
  table
      .add_number("mesh.echinocyte.membrane_area_um2", "um^2", shape.membrane_area_um2,
                  "Membrane area (the discocyte's: area is conserved through the shape change).")
      .above(0.0);
  table
      .add_integer("mesh.echinocyte.spicule_count", "", shape.spicule_count,
                   "Number of spicules (the paper: about 30-50).")
      .at_least(1)
      .at_most(200);
  table
      .add_number("mesh.echinocyte.spicule_height_um", "um", shape.spicule_height_um,
                  "Height of a spicule tip above the body surface.")
      .above(0.0);
  table
      .add_number("mesh.echinocyte.spicule_tip_radius_um", "um", shape.spicule_tip_radius_um,
                  "Radius of the rounded spicule tip.")
      .above(0.0);
  table
      .add_number("mesh.echinocyte.spicule_flank_angle_deg", "deg", shape.spicule_flank_angle_deg,
                  "Angle of the spicule's conical flank against the body surface.")
      .above(0.0)
      .below(90.0);
  table
      .add_number("mesh.echinocyte.spicule_base_blend_um", "um", shape.spicule_base_blend_um,
                  "Width of the smooth fillet between flank and body.")
      .above(0.0);
}

// The bilayer-couple model of the energy-minimised shapes (shapes/energy_shape.hpp): literature
// values (Lim, Wortis & Mukhopadhyay 2002) and the path the minimiser takes.
void add_energy_model_options(OptionTable& table) {
  const shapes::EnergyShapeSettings defaults;
  table
      .add_number("mesh.energy.membrane_area_um2", "um^2", defaults.area_um2,
                  "Membrane area held by the minimisation (Evans-Fung's discocyte: the shape "
                  "change conserves it).")
      .above(0.0);
  table
      .add_number("mesh.energy.reduced_volume", "", defaults.reduced_volume,
                  "Reduced volume 6 sqrt(pi) V / A^1.5 held by the minimisation (Lim et al. 2002 "
                  "keep 0.642 along the whole sequence).")
      .above(0.0)
      .below(1.0);
  table
      .add_number("mesh.energy.bending_modulus_J", "J", defaults.bending_modulus_J,
                  "Helfrich bending modulus kappa of the bilayer (Lim et al. 2002).")
      .above(0.0);
  table
      .add_number("mesh.energy.nonlocal_bending_ratio", "", defaults.nonlocal_bending_ratio,
                  "Area-difference elasticity modulus over kappa, alpha (Lim et al. 2002: 2/pi).")
      .at_least(0.0);
  table
      .add_number("mesh.energy.shear_modulus_uN_per_m", "uN/m",
                  defaults.skeleton.shear_modulus_pN_per_um,
                  "Shear modulus mu of the membrane skeleton (Lim et al. 2002).")
      .above(0.0);
  table
      .add_number("mesh.energy.area_modulus_uN_per_m", "uN/m",
                  defaults.skeleton.area_modulus_pN_per_um,
                  "Stretch (area) modulus K_alpha of the skeleton (Lim et al. 2002: 2 mu).")
      .above(0.0);
  table.add_number("mesh.energy.skeleton_a3", "", defaults.skeleton.a3,
                   "Cubic dilation coefficient of Lim's skeleton energy.");
  table.add_number("mesh.energy.skeleton_a4", "", defaults.skeleton.a4,
                   "Quartic dilation coefficient of Lim's skeleton energy.");
  table.add_number("mesh.energy.skeleton_b1", "", defaults.skeleton.b1,
                   "Dilation-shear coupling coefficient of Lim's skeleton energy.");
  table.add_number("mesh.energy.skeleton_b2", "", defaults.skeleton.b2,
                   "Quadratic shear coefficient of Lim's skeleton energy.");
  table
      .add_number("mesh.energy.skeleton_reference_reduced_volume", "",
                  defaults.skeleton_reference_reduced_volume,
                  "Reduced volume of the skeleton's stress-free shape, an oblate spheroid of the "
                  "membrane's area (near-spherical, as Lim et al.'s).")
      .above(0.0)
      .below(1.0);
  for (const auto& shape : shapes::shape_sequence().entries()) {
    table.add_choice_list("mesh.energy.paths." + std::string(shape.name),
                          shapes::energy_paths().names(), shape.paths,
                          "Paths from the reference every trial of the " + std::string(shape.name) +
                              " follows (the lowest valid minimum wins): " +
                              shapes::energy_paths().described_names() + ".");
    table
        .add_integer("mesh.energy.trials." + std::string(shape.name), "", shape.trials,
                     "Seeded starts of each path of the " + std::string(shape.name) +
                         "; the lowest energy wins.")
        .at_least(1)
        .at_most(100);
    table.add_number("mesh.energy.relaxed_area_difference." + std::string(shape.name), "",
                     shape.relaxed_area_difference,
                     "Reduced relaxed area difference Delta a0 of the " + std::string(shape.name) +
                         " (" + std::string(shape.description) + ").");
  }
}

void add_energy_path_options(OptionTable& table) {
  const shapes::EnergyShapeSettings defaults;

  table
      .add_number("mesh.energy.soft_skeleton_fraction", "", defaults.soft_skeleton_fraction,
                  "The skeleton's moduli during deflation, relative to their values (a nearly "
                  "fluid membrane first, then stiffened).")
      .above(0.0)
      .at_most(1.0);
  table
      .add_integer("mesh.energy.volume_stages", "", defaults.volume_stages,
                   "Equal steps of the deflation from the reference's volume to the target's.")
      .at_least(1);
  table
      .add_integer("mesh.energy.stiffening_stages", "", defaults.stiffening_stages,
                   "Geometric steps from the soft to the full skeleton.")
      .at_least(1);
  table
      .add_number("mesh.energy.continuation_start_area_difference", "",
                  defaults.continuation_start_area_difference,
                  "The continuation path deflates at this relaxed area difference (the "
                  "discocyte's), then walks it to the shape's.")
      .at_least(shapes::kReachableAreaDifference[0])
      .at_most(shapes::kReachableAreaDifference[1]);
  table
      .add_number("mesh.energy.continuation_step", "", defaults.continuation_step,
                  "The continuation path's largest step in relaxed area difference.")
      .above(0.0);
  table
      .add_integer("mesh.energy.stage_iterations", "", static_cast<int>(defaults.stage_iterations),
                   "FIRE iterations per stage of the path, at most.")
      .at_least(1);
  table
      .add_integer("mesh.energy.seed", "", static_cast<int>(defaults.seed),
                   "Seed of the first trial's random start (trial k uses seed + k).")
      .at_least(0);
  table
      .add_number("mesh.energy.perturbation_um", "um", defaults.perturbation_um,
                  "Amplitude of the seeded random displacement of every vertex at every stage "
                  "(breaks symmetries the minimum must not inherit from the icosphere).")
      .at_least(0.0);
  table
      .add_number("mesh.energy.force_tolerance_pN", "pN", defaults.force_tolerance_pN,
                  "Converged when no vertex's force (tangent to the held area and volume) exceeds "
                  "this.")
      .above(0.0);
  table
      .add_integer(
          "mesh.energy.max_iterations", "", static_cast<int>(defaults.max_iterations),
          "FIRE iterations of the final minimisation, at most; more is a failure (exit 1).")
      .at_least(1);
  table
      .add_integer("mesh.energy.redistribution_sweeps", "", defaults.redistribution.iterations,
                   "Sweeps of tangential smoothing that slide the minimum's vertices over its own "
                   "surface to even out its triangles before it becomes the stress-free mesh "
                   "(reduced volume and area then restored); kept only if its smallest angle "
                   "grows. 0 ships the minimum as found.")
      .at_least(0)
      .at_most(100000);
  table
      .add_number("mesh.energy.redistribution_step", "", defaults.redistribution.step_fraction,
                  "Fraction of the way to its triangles' area-weighted centroid a vertex slides "
                  "per sweep.")
      .above(0.0)
      .at_most(1.0);
}

}  // namespace

void add_mesh_options(OptionTable& table) {
  table.add_choice(
      "mesh.method", shapes::shape_methods().names(), "energy",
      "How a built-in shape is made: " + shapes::shape_methods().described_names() + ".");
  table.add_string("mesh.file", "",
                   "Cell mesh to import (STL, OBJ, PLY, OFF); empty: generate the morphology's "
                   "built-in shape.");
  // Level 4 is the paper's 2562-vertex cell; level 6 already has 40962 vertices.
  table
      .add_integer("mesh.subdivisions", "", 4,
                   "Icosphere subdivision level of the built-in shape (4: 2562 vertices).")
      .at_least(1)
      .at_most(6);
  table
      .add_integer("mesh.max_triangles", "", static_cast<int>(mesh::kDefaultMaxTriangles),
                   "Largest mesh.file accepted, in triangles; a larger file is refused before it "
                   "is read.")
      .at_least(4);
  add_discocyte_options(table);
  add_stomatocyte_options(table);
  add_echinocyte_options(table);
  add_energy_model_options(table);
  add_energy_path_options(table);
}

}  // namespace rbcsim::config
