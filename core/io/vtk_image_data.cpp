#include "io/vtk_image_data.hpp"

#include <iomanip>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace rbcsim::io {

std::size_t ImageGrid::point_count() const {
  return static_cast<std::size_t>(point_counts[0]) * static_cast<std::size_t>(point_counts[1]) *
         static_cast<std::size_t>(point_counts[2]);
}

void write_vtk_image_data(std::ostream& out, const ImageGrid& grid,
                          std::span<const PointDataArray> point_arrays, VtkEncoding encoding) {
  for (const int count : grid.point_counts) {
    if (count < 1) throw std::invalid_argument("VTK image: every axis needs at least one point");
  }
  check_point_arrays(grid.point_count(), point_arrays);
  const auto& n = grid.point_counts;
  const std::string extent = "0 " + std::to_string(n[0] - 1) + " 0 " + std::to_string(n[1] - 1) +
                             " 0 " + std::to_string(n[2] - 1);
  // Round-trip precision for the geometry: node positions must overlay the membrane exactly.
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"1.0\" " << vtk_file_attributes() << ">\n"
      << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"" << grid.origin_um.x() << ' '
      << grid.origin_um.y() << ' ' << grid.origin_um.z() << "\" Spacing=\"" << grid.spacing_um
      << ' ' << grid.spacing_um << ' ' << grid.spacing_um << "\">\n"
      << "    <Piece Extent=\"" << extent << "\">\n"
      << "      <PointData>\n";
  for (const auto& array : point_arrays) write_data_array(out, array, encoding, "        ");
  out << "      </PointData>\n      <CellData>\n      </CellData>\n"
      << "    </Piece>\n  </ImageData>\n</VTKFile>\n";
}

void write_vtk_image_data(const std::filesystem::path& path, const ImageGrid& grid,
                          std::span<const PointDataArray> point_arrays, VtkEncoding encoding) {
  write_file_atomically(
      path, [&](std::ostream& out) { write_vtk_image_data(out, grid, point_arrays, encoding); });
}

}  // namespace rbcsim::io
