#include "io/vtk_polydata.hpp"

#include <iomanip>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace rbcsim::io {
namespace {

constexpr int kSignificantDigits = 9;

void check(std::size_t point_count, std::span<const std::array<std::int32_t, 3>> triangles,
           std::span<const PointDataArray> point_arrays) {
  for (const auto& array : point_arrays) {
    if (array.name.empty() || array.name.find_first_of("<>&\"'") != std::string::npos) {
      throw std::invalid_argument("VTK point array name '" + array.name +
                                  "' must be non-empty plain text (no XML markup characters)");
    }
    if (array.component_count != 1 && array.component_count != 3) {
      throw std::invalid_argument("VTK point array '" + array.name +
                                  "' must have 1 or 3 components");
    }
    if (array.values.size() != point_count * static_cast<std::size_t>(array.component_count)) {
      throw std::invalid_argument("VTK point array '" + array.name + "' has " +
                                  std::to_string(array.values.size()) + " values for " +
                                  std::to_string(point_count) + " points");
    }
  }
  for (const auto& triangle : triangles) {
    for (auto v : triangle) {
      if (v < 0 || static_cast<std::size_t>(v) >= point_count) {
        throw std::invalid_argument("VTK triangle refers to missing point " + std::to_string(v));
      }
    }
  }
}

template <typename Range, typename Write>
void data_array(std::ostream& out, const std::string& attributes, const Range& items, Write write) {
  out << "        <DataArray " << attributes << " format=\"ascii\">\n";
  for (const auto& item : items) {
    out << "          ";
    write(item);
    out << '\n';
  }
  out << "        </DataArray>\n";
}

}  // namespace

PointDataArray scalar_point_array(std::string name, std::span<const double> values) {
  return {std::move(name), 1, values};
}

PointDataArray vector_point_array(std::string name, std::span<const Vec3> values) {
  // Eigen::Vector3d is three contiguous doubles without padding.
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  return {
      std::move(name), 3,
      std::span<const double>(values.empty() ? nullptr : values.front().data(), 3 * values.size())};
}

void write_vtk_polydata(std::ostream& out, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays) {
  check(points_um.size(), triangles, point_arrays);
  out << std::setprecision(kSignificantDigits);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << points_um.size() << "\" NumberOfVerts=\"0\" "
      << "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" << triangles.size() << "\">\n";
  out << "      <PointData>\n";
  for (const auto& array : point_arrays) {
    out << "        <DataArray type=\"Float64\" Name=\"" << array.name << "\" NumberOfComponents=\""
        << array.component_count << "\" format=\"ascii\">\n";
    for (std::size_t p = 0; p < points_um.size(); ++p) {
      out << "         ";
      for (int c = 0; c < array.component_count; ++c) {
        out << ' ' << array.values[p * static_cast<std::size_t>(array.component_count) + c];
      }
      out << '\n';
    }
    out << "        </DataArray>\n";
  }
  out << "      </PointData>\n      <Points>\n";
  data_array(out, "type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"", points_um,
             [&out](const Vec3& p) { out << p.x() << ' ' << p.y() << ' ' << p.z(); });
  out << "      </Points>\n      <Polys>\n";
  data_array(out, "type=\"Int32\" Name=\"connectivity\"", triangles,
             [&out](const auto& t) { out << t[0] << ' ' << t[1] << ' ' << t[2]; });
  std::vector<std::int64_t> offsets(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    offsets[t] = 3 * static_cast<std::int64_t>(t + 1);
  data_array(out, "type=\"Int64\" Name=\"offsets\"", offsets, [&out](std::int64_t o) { out << o; });
  out << "      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

void write_vtk_polydata(const std::filesystem::path& path, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays) {
  write_file_atomically(path, [&](std::ostream& out) {
    write_vtk_polydata(out, points_um, triangles, point_arrays);
  });
}

}  // namespace rbcsim::io
