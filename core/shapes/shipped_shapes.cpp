#include "shapes/shipped_shapes.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "mesh/icosphere.hpp"

namespace rbcsim::shapes {
namespace {

constexpr std::size_t kStlHeaderBytes = 84;
constexpr std::size_t kStlTriangleBytes = 50;

float read_float(std::string_view bytes, std::size_t offset) {
  float value = 0.0F;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

const nlohmann::json& manifest() {
  static const nlohmann::json parsed = [] {
    const auto text = find_embedded_file(embedded_mesh_files(), "manifest.json");
    return text ? nlohmann::json::parse(*text) : nlohmann::json::object();
  }();
  return parsed;
}

}  // namespace

mesh::TriangleMesh read_icosphere_stl(std::string_view bytes, int subdivisions) {
  auto mesh = mesh::unit_icosphere(subdivisions);
  const std::size_t count = mesh.triangles.size();
  if (bytes.size() != kStlHeaderBytes + count * kStlTriangleBytes) {
    throw std::runtime_error("not a binary STL of the level-" + std::to_string(subdivisions) +
                             " icosphere (" + std::to_string(bytes.size()) + " bytes)");
  }
  std::vector<bool> seen(mesh.vertex_count(), false);
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t offset = kStlHeaderBytes + t * kStlTriangleBytes + 12;  // after the normal
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3 corner(read_float(bytes, offset + 12 * k), read_float(bytes, offset + 12 * k + 4),
                        read_float(bytes, offset + 12 * k + 8));
      const auto vertex = static_cast<std::size_t>(mesh.triangles[t][k]);
      if (seen[vertex] && mesh.positions_um[vertex] != corner) {
        throw std::runtime_error("vertex " + std::to_string(vertex) +
                                 " has two positions: not the icosphere's connectivity");
      }
      mesh.positions_um[vertex] = corner;
      seen[vertex] = true;
    }
  }
  return mesh;
}

std::optional<ShippedShape> find_shipped_shape(std::string_view method, std::string_view shape,
                                               int subdivisions,
                                               const nlohmann::ordered_json& settings) {
  const auto& entries = manifest().value("meshes", nlohmann::json::array());
  const auto wanted = nlohmann::json::parse(settings.dump());  // ordered -> plain, for equality
  for (const auto& entry : entries) {
    if (entry.value("method", "") != method || entry.value("shape", "") != shape ||
        entry.value("subdivisions", -1) != subdivisions ||
        entry.value("settings", nlohmann::json()) != wanted) {
      continue;
    }
    const auto bytes = find_embedded_file(embedded_mesh_files(), entry.value("output", ""));
    if (!bytes) return std::nullopt;
    return ShippedShape{read_icosphere_stl(*bytes, subdivisions), entry};
  }
  return std::nullopt;
}

}  // namespace rbcsim::shapes
