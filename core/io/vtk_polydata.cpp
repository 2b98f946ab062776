#include "io/vtk_polydata.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"

namespace rbcsim::io {
namespace {

void check_triangles(std::size_t point_count,
                     std::span<const std::array<std::int32_t, 3>> triangles) {
  for (const auto& triangle : triangles) {
    for (auto v : triangle) {
      if (v < 0 || static_cast<std::size_t>(v) >= point_count) {
        throw std::invalid_argument("VTK triangle refers to missing point " + std::to_string(v));
      }
    }
  }
}

}  // namespace

void write_vtk_polydata(std::ostream& out, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays, VtkEncoding encoding) {
  check_point_arrays(points_um.size(), point_arrays);
  check_triangles(points_um.size(), triangles);
  constexpr std::string_view kIndent = "        ";
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" " << vtk_file_attributes() << ">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << points_um.size() << "\" NumberOfVerts=\"0\" "
      << "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" << triangles.size() << "\">\n";
  out << "      <PointData>\n";
  for (const auto& array : point_arrays) write_data_array(out, array, encoding, kIndent);
  out << "      </PointData>\n      <Points>\n";
  write_data_array(out, vector_point_array("Points", points_um), encoding, kIndent);
  out << "      </Points>\n      <Polys>\n";
  // std::array<int32_t, 3> holds three contiguous values.
  static_assert(sizeof(std::array<std::int32_t, 3>) == 3 * sizeof(std::int32_t));
  const std::span<const std::int32_t> connectivity(
      triangles.empty() ? nullptr : triangles.front().data(), 3 * triangles.size());
  write_data_array(out, {"connectivity", 1, connectivity}, encoding, kIndent);
  std::vector<std::int64_t> offsets(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    offsets[t] = 3 * static_cast<std::int64_t>(t + 1);
  }
  write_data_array(out, {"offsets", 1, std::span<const std::int64_t>(offsets)}, encoding, kIndent);
  out << "      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

void write_vtk_polydata(const std::filesystem::path& path, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays, VtkEncoding encoding) {
  write_file_atomically(path, [&](std::ostream& out) {
    write_vtk_polydata(out, points_um, triangles, point_arrays, encoding);
  });
}

}  // namespace rbcsim::io
