#include "mesh/cell_shapes.hpp"

#include <array>

#include "common/errors.hpp"
#include "mesh/discocyte.hpp"
#include "mesh/echinocyte.hpp"
#include "mesh/stomatocyte.hpp"

namespace rbcsim::mesh {
namespace {

constexpr int kMaxSubdivisions = 7;  // 163842 vertices: beyond, memory and time explode

const std::array kCellShapes = {
    CellShapeEntry{"discocyte", "healthy biconcave disc (Evans & Fung 1972)",
                   [](int n) { return discocyte_mesh({}, n); }},
    CellShapeEntry{"stomatocyte-II", "cup with a deep invagination (thickened spherical cap)",
                   [](int n) { return stomatocyte_mesh({}, n); }},
    CellShapeEntry{"echinocyte-III", "sphere with 36 evenly spaced rounded spicules",
                   [](int n) { return echinocyte_mesh({}, n); }},
};

}  // namespace

std::span<const CellShapeEntry> cell_shapes() { return kCellShapes; }

std::string cell_shape_names() {
  std::string names;
  for (const auto& entry : kCellShapes) {
    if (!names.empty()) names += ", ";
    names += entry.name;
  }
  return names;
}

TriangleMesh generate_cell(std::string_view shape_name, int subdivisions) {
  if (subdivisions < 0 || subdivisions > kMaxSubdivisions) {
    throw InputError("--subdivisions", "must be in 0.." + std::to_string(kMaxSubdivisions) +
                                           ", got " + std::to_string(subdivisions));
  }
  for (const auto& entry : kCellShapes) {
    if (entry.name == shape_name) return entry.generate(subdivisions);
  }
  throw InputError("--shape", "unknown cell shape '" + std::string(shape_name) +
                                  "' (known: " + cell_shape_names() + ")");
}

}  // namespace rbcsim::mesh
