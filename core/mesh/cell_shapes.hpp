// The generated cell morphologies, by name: ONE table (cell_shapes.cpp) maps each name to its
// generator, so adding a shape is adding a file and a row.
#pragma once

#include <optional>
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
  // The shape has features a coarse mesh may not resolve (the echinocyte's spicules), so a
  // generated mesh is compared with the next level (resolution_notice).
  bool has_fine_features = false;
};

std::span<const CellShapeEntry> cell_shapes();

// "discocyte, stomatocyte-II, echinocyte-III": for help texts and error messages.
std::string cell_shape_names();

// Throws rbcsim::InputError for an unknown name (listing the known ones) or a subdivision level
// outside 0..7.
TriangleMesh generate_cell(std::string_view shape_name, int subdivisions,
                           const CellShapeParameters& parameters = {});

// A coarse mesh of a shape with fine features misses part of their area, and the generator, which
// matches the membrane area, inflates the body to make up for it: the echinocyte III at level 3
// (642 vertices) has a reduced volume of 0.76, at levels 4 / 5 / 6 0.652 / 0.630 / 0.625
// (measured). So for such a shape (CellShapeEntry::has_fine_features) the reduced volume of
// `mesh`, generated at `subdivisions`, is compared with that of the next level; a change of more
// than kResolvedReducedVolumeChange gets a notice naming both, else nullopt. If the next level
// cannot be generated (its finer mesh finds more feature area than the membrane has), the notice
// says that instead. Smooth shapes and the finest level get nullopt without generating anything.
// Two unresolved levels can agree by chance (50 spicules 1.3 um high at levels 2 and 3): the check
// catches the default echinocyte at 642 vertices, not every coarse shape.
inline constexpr double kResolvedReducedVolumeChange = 0.05;
std::optional<std::string> resolution_notice(std::string_view shape_name, int subdivisions,
                                             const CellShapeParameters& parameters,
                                             const TriangleMesh& mesh);

}  // namespace rbcsim::mesh
