#include "mesh/cell_shapes.hpp"

#include <array>

#include "common/errors.hpp"

namespace rbcsim::mesh {
namespace {

constexpr int kMaxSubdivisions = 7;  // 163842 vertices: beyond, memory and time explode

const std::array kCellShapes = {
    CellShapeEntry{
        "discocyte", "healthy biconcave disc (Evans & Fung 1972)",
        [](const CellShapeParameters& p, int n) { return discocyte_mesh(p.discocyte, n); }},
    CellShapeEntry{
        "stomatocyte-II", "cup with a deep invagination (thickened spherical cap)",
        [](const CellShapeParameters& p, int n) { return stomatocyte_mesh(p.stomatocyte, n); }},
    CellShapeEntry{
        "echinocyte-III", "sphere with 36 evenly spaced rounded spicules",
        [](const CellShapeParameters& p, int n) { return echinocyte_mesh(p.echinocyte, n); }},
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

TriangleMesh generate_cell(std::string_view shape_name, int subdivisions,
                           const CellShapeParameters& parameters) {
  if (subdivisions < 0 || subdivisions > kMaxSubdivisions) {
    throw InputError("--subdivisions", "must be in 0.." + std::to_string(kMaxSubdivisions) +
                                           ", got " + std::to_string(subdivisions));
  }
  for (const auto& entry : kCellShapes) {
    if (entry.name == shape_name) return entry.generate(parameters, subdivisions);
  }
  throw InputError("--shape", "unknown cell shape '" + std::string(shape_name) +
                                  "' (known: " + cell_shape_names() + ")");
}

}  // namespace rbcsim::mesh
