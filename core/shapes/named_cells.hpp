// The cell a built-in name stands for ("discocyte", "stomatocyte-II", ...), made by a method
// chosen by name (mesh.method):
//   energy      the bilayer-couple minimum of the sequence shape (energy_shape.hpp, sequence.hpp),
//               taken from the shipped meshes when the settings are theirs (shipped_shapes.hpp);
//   parametric  the drawn generators of core/mesh (the Evans-Fung discocyte, a bent thick shell,
//               a sphere with spicules on a spiral).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/registry.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/triangle_mesh.hpp"
#include "shapes/energy_shape.hpp"

namespace rbcsim::shapes {

struct ShapeMethod {
  std::string_view name;
  std::string_view description;
  std::vector<std::string> (*shape_names)();  // what the method can make
};
const Registry<ShapeMethod>& shape_methods();

struct NamedCellSettings {
  std::string method = "energy";
  int subdivisions = 4;
  // For `energy`: relaxed_area_difference must already be the requested shape's.
  EnergyShapeSettings energy;
  mesh::CellShapeParameters parametric;
  bool use_shipped = true;  // false: minimise even when a shipped shape matches
};

struct NamedCell {
  mesh::TriangleMesh mesh;
  std::string source;                    // "built-in discocyte level 4" (mesh.method says how)
  std::optional<EnergyShape> minimised;  // when this call minimised
  nlohmann::json shipped_entry;          // when taken from meshes/: its manifest entry
};

// Throws InputError(shape_key, ...) for a name the method cannot make (listing those it can),
// InputError(mesh.method) for an unknown method, and what minimise_shape throws.
NamedCell make_named_cell(std::string_view shape, std::string_view shape_key,
                          const NamedCellSettings& settings,
                          const EnergyShapeProgress& progress = {});

}  // namespace rbcsim::shapes
