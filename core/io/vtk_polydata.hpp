// VTK XML PolyData (.vtp) output of a triangulated surface with per-point data arrays, readable by
// ParaView and VTK: the membrane snapshots (one 3-vector array per force term) and `mesh` output.
// ASCII format with 9 significant digits (more than float32 rendering needs; exact round trips
// are the job of the binary STL and the run state, not of visualisation files).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::io {

struct PointDataArray {
  std::string name;
  int component_count = 1;         // 1 (scalar) or 3 (vector)
  std::span<const double> values;  // component_count values per point, point after point
};

PointDataArray scalar_point_array(std::string name, std::span<const double> values);
PointDataArray vector_point_array(std::string name, std::span<const Vec3> values);

// Throws std::invalid_argument if an array does not have one value (or 3-vector) per point, or a
// triangle refers to a missing point.
void write_vtk_polydata(std::ostream& out, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays);
// Through write_file_atomically.
void write_vtk_polydata(const std::filesystem::path& path, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays);

}  // namespace rbcsim::io
