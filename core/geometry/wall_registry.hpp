// The one table of wall shapes, chosen by name in a config: "channel", "tube", "capillary",
// "paper-validation", "paper-morphology", "stl". Adding a shape = its class file plus one reader
// and one row in wall_registry.cpp.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/shape_parameters.hpp"
#include "geometry/wall_shape.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::geometry {

// Reads a wall surface file (the mesh importer of core/mesh); it throws rbcsim::InputError naming
// the file for a file it cannot read. Only the "stl" shape uses it.
using MeshLoader = std::function<mesh::TriangleMesh(const std::string& path)>;

struct WallShapeKind {
  std::string_view name;
  std::string_view summary;  // one line: what it is and its parameters (lengths in um)
  std::unique_ptr<WallShape> (*read)(ParameterReader& parameters, const MeshLoader& load_mesh);
};

std::span<const WallShapeKind> wall_shape_kinds();

// The kinds that are the paper's own capillaries (named "paper-..."), in table order: the choices
// of capillary.geometry.
std::vector<std::string> paper_capillary_names();

// Builds the shape `name` from a JSON object of its parameters (keys as in its summary; null = no
// parameters). Throws rbcsim::InputError naming json_path for an unknown shape, and
// json_path.<key> for a missing, mistyped, unknown or invalid parameter.
std::unique_ptr<WallShape> make_wall_shape(std::string_view name,
                                           const nlohmann::json& parameters = nullptr,
                                           std::string_view json_path = "geometry",
                                           const MeshLoader& load_mesh = {});

}  // namespace rbcsim::geometry
