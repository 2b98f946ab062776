// The generated cell morphologies, by name: ONE table (cell_shapes.cpp) maps each name to its
// generator, so adding a shape is adding a file and a row.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "mesh/discocyte.hpp"
#include "mesh/echinocyte.hpp"
#include "mesh/stomatocyte.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

// The parameters of every generator; each generator reads its own member. The config options
// mesh.discocyte.*, mesh.stomatocyte.*, mesh.echinocyte.* fill it (core/setup).
struct CellShapeParameters {
  DiscocyteShape discocyte;
  StomatocyteShape stomatocyte;
  EchinocyteShape echinocyte;
};

struct CellShapeEntry {
  std::string_view name;         // as on the command line: "discocyte", ...
  std::string_view description;  // one line for --help and reports
  TriangleMesh (*generate)(const CellShapeParameters& parameters, int subdivisions);
};

std::span<const CellShapeEntry> cell_shapes();

// "discocyte, stomatocyte-II, echinocyte-III": for help texts and error messages.
std::string cell_shape_names();

// Throws rbcsim::InputError for an unknown name (listing the known ones) or a subdivision level
// outside 0..7.
TriangleMesh generate_cell(std::string_view shape_name, int subdivisions,
                           const CellShapeParameters& parameters = {});

}  // namespace rbcsim::mesh
