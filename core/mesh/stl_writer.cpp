#include "mesh/stl_writer.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>

#include "common/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/vtk_polydata.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::mesh {
namespace {

static_assert(std::endian::native == std::endian::little,
              "binary STL is little-endian; add byte swapping for this platform");

void put_vector(char*& cursor, const Vec3& v) {
  for (int k = 0; k < 3; ++k) {
    const auto value = static_cast<float>(v[k]);
    std::memcpy(cursor, &value, sizeof value);
    cursor += sizeof value;
  }
}

}  // namespace

void write_stl_binary(std::ostream& out, const TriangleMesh& mesh) {
  if (mesh.triangle_count() > std::numeric_limits<std::uint32_t>::max()) {
    throw RuntimeFailure("mesh has too many triangles for binary STL");
  }
  std::array<char, 80> header{};
  constexpr char kTitle[] = "rbcsim binary STL, coordinates in micrometres";
  std::copy(std::begin(kTitle), std::end(kTitle) - 1, header.begin());
  out.write(header.data(), header.size());
  const auto count = static_cast<std::uint32_t>(mesh.triangle_count());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  std::array<char, 50> record{};  // normal, 3 vertices (12 float32), uint16 attribute = 0
  for (const auto& t : mesh.triangles) {
    char* cursor = record.data();
    const Vec3 area_vector = triangle_area_vector(mesh.positions_um, t);
    const double area = area_vector.norm();
    put_vector(cursor, area > 0.0 ? Vec3(area_vector / area) : Vec3::Zero());
    for (auto v : t) put_vector(cursor, mesh.positions_um[v]);
    out.write(record.data(), record.size());
  }
}

void write_stl_binary(const std::filesystem::path& path, const TriangleMesh& mesh) {
  io::write_file_atomically(path, [&mesh](std::ostream& out) { write_stl_binary(out, mesh); });
}

namespace {
bool is_stl(const std::filesystem::path& path) {
  const auto extension = path.extension().string();
  return extension == ".stl" || extension == ".STL";
}
}  // namespace

void require_mesh_file_format(const std::filesystem::path& path) {
  if (is_stl(path) || path.extension() == ".vtp") return;
  throw InputError(path.string(),
                   "unknown output format '" + path.extension().string() + "' (use .stl or .vtp)");
}

void write_mesh_file(const std::filesystem::path& path, const TriangleMesh& mesh) {
  require_mesh_file_format(path);
  if (is_stl(path)) {
    write_stl_binary(path, mesh);
  } else {
    io::write_vtk_polydata(path, mesh.positions_um, mesh.triangles, {});
  }
}

}  // namespace rbcsim::mesh
