// VTK XML PolyData (.vtp) output of a triangulated surface with per-point data arrays, readable by
// ParaView and VTK: the membrane snapshots (one 3-vector array per force term) and `mesh` output.
// ASCII by default (readable; exact round trips are the job of the binary STL and the run state),
// base64 for the simulation's snapshots (vtk_data_array.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <span>

#include "common/vec3.hpp"
#include "io/vtk_data_array.hpp"

namespace rbcsim::io {

// Throws std::invalid_argument if an array does not have one value (or 3-vector) per point, or a
// triangle refers to a missing point.
void write_vtk_polydata(std::ostream& out, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays,
                        VtkEncoding encoding = VtkEncoding::ascii);
// Through write_file_atomically.
void write_vtk_polydata(const std::filesystem::path& path, std::span<const Vec3> points_um,
                        std::span<const std::array<std::int32_t, 3>> triangles,
                        std::span<const PointDataArray> point_arrays,
                        VtkEncoding encoding = VtkEncoding::ascii);

}  // namespace rbcsim::io
