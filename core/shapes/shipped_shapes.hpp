// The cell shapes shipped in meshes/ (scripts/regenerate_meshes.sh: `rbcsim mesh generate --json`
// of every named shape at the shipped levels), compiled into the binary with meshes/manifest.json.
// An energy-minimised shape takes minutes at 2562 vertices; a run whose mesh.energy settings are
// exactly a shipped shape's takes the shipped mesh instead, which is that minimisation's result
// bit for bit (its coordinates are single precision in the STL and in the generator alike; the
// validate target regenerates them and compares).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "common/embedded_file.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::shapes {

// meshes/manifest.json and the meshes/*.stl it lists, as built into the binary.
std::span<const EmbeddedFile> embedded_mesh_files();

struct ShippedShape {
  mesh::TriangleMesh mesh;
  nlohmann::json entry;  // its manifest entry: the `mesh generate --json` output it was made with
};

// The shipped shape made by `method` for `shape` at `subdivisions` with exactly `settings` (the
// method's settings as its generator prints them), or nullopt.
std::optional<ShippedShape> find_shipped_shape(std::string_view method, std::string_view shape,
                                               int subdivisions,
                                               const nlohmann::ordered_json& settings);

// A binary STL of the icosphere's connectivity at `subdivisions` (as the generators write it):
// the positions of its vertices, the triangles those of unit_icosphere(subdivisions). Throws
// std::runtime_error when the bytes are not such a file.
mesh::TriangleMesh read_icosphere_stl(std::string_view bytes, int subdivisions);

}  // namespace rbcsim::shapes
