#include "config/options/option_areas.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/import.hpp"

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

}  // namespace

void add_mesh_options(OptionTable& table) {
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
}

}  // namespace rbcsim::config
