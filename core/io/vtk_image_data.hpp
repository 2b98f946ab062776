// VTK XML ImageData (.vti) output of fields on a uniform grid, readable by ParaView and VTK: the
// lattice fluid's velocity, density and solid mask. Point (i, j, k) is value number
// i + nx * (j + ny * k) of each array (x fastest), the lattice's own order, and sits at
// origin + spacing * (i, j, k): the node-centred convention of the lattice, in the same length
// unit (um) as the membrane .vtp files so both overlay in ParaView.
#pragma once

#include <array>
#include <filesystem>
#include <ostream>
#include <span>

#include "common/vec3.hpp"
#include "io/vtk_data_array.hpp"

namespace rbcsim::io {

struct ImageGrid {
  std::array<int, 3> point_counts = {1, 1, 1};  // nx, ny, nz, each at least 1
  Vec3 origin_um = Vec3::Zero();
  double spacing_um = 1.0;

  std::size_t point_count() const;
};

// Throws std::invalid_argument for a point count below 1 or an array that does not have one value
// (or 3-vector) per point.
void write_vtk_image_data(std::ostream& out, const ImageGrid& grid,
                          std::span<const PointDataArray> point_arrays,
                          VtkEncoding encoding = VtkEncoding::base64);
// Through write_file_atomically.
void write_vtk_image_data(const std::filesystem::path& path, const ImageGrid& grid,
                          std::span<const PointDataArray> point_arrays,
                          VtkEncoding encoding = VtkEncoding::base64);

}  // namespace rbcsim::io
