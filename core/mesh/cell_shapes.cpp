#include "mesh/cell_shapes.hpp"

#include <array>
#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/registry.hpp"
#include "mesh/inspection.hpp"

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
        [](const CellShapeParameters& p, int n) { return echinocyte_mesh(p.echinocyte, n); },
        /*has_fine_features=*/true},
};

const CellShapeEntry& find_cell_shape(std::string_view shape_name) {
  return find_entry(kCellShapes, shape_name, "--shape");
}

}  // namespace

std::span<const CellShapeEntry> cell_shapes() { return kCellShapes; }

std::string cell_shape_names() { return joined_entry_names(kCellShapes); }

TriangleMesh generate_cell(std::string_view shape_name, int subdivisions,
                           const CellShapeParameters& parameters) {
  if (subdivisions < 0 || subdivisions > kMaxSubdivisions) {
    throw InputError("--subdivisions", "must be in 0.." + std::to_string(kMaxSubdivisions) +
                                           ", got " + std::to_string(subdivisions));
  }
  return find_cell_shape(shape_name).generate(parameters, subdivisions);
}

std::optional<std::string> resolution_notice(std::string_view shape_name, int subdivisions,
                                             const CellShapeParameters& parameters,
                                             const TriangleMesh& mesh) {
  const auto& entry = find_cell_shape(shape_name);
  if (!entry.has_fine_features || subdivisions >= kMaxSubdivisions) return std::nullopt;
  const auto coarse = inspect_mesh(mesh);
  const auto at_level =
      std::string(shape_name) + " at mesh.subdivisions = " + std::to_string(subdivisions);
  const auto edges = "its edges (mean " + format_significant(coarse.edge_mean_um, 2) + " um)";
  const auto finer_level = std::to_string(subdivisions + 1);
  MeshReport finer;
  try {
    finer = inspect_mesh(entry.generate(parameters, subdivisions + 1));
  } catch (const InputError& error) {
    // The finer mesh finds more feature area than the membrane has: the shape asked for does not
    // exist, and this level's coarse edges hide it. Told, not an error: this level was generated.
    return at_level + ": " + edges + " hide that the shape's features need more area than the " +
           "membrane has (at level " + finer_level + ": " + error.what() +
           "); change the shape's parameters";
  }
  const double change = coarse.reduced_volume / finer.reduced_volume - 1.0;
  if (std::abs(change) <= kResolvedReducedVolumeChange) return std::nullopt;
  return at_level + " has a reduced volume of " + format_significant(coarse.reduced_volume, 3) +
         ", " + format_significant(100.0 * std::abs(change), 2) +
         (change > 0 ? " % above" : " % below") + " the " +
         format_significant(finer.reduced_volume, 3) + " at level " + finer_level + ": " + edges +
         " do not resolve the shape's features, and the generator, matching the membrane area, "
         "made up for them with the body; use a finer level";
}

}  // namespace rbcsim::mesh
