// One <DataArray> element of a VTK XML file, shared by every VTK writer of rbcsim (.vtp membranes
// and meshes, .vti fluid fields): the value types VTK names, the checks, and two encodings.
//   ascii   readable text, 9 significant digits (more than float32 rendering needs);
//   base64  VTK's inline "binary" format: the raw little-endian bytes behind a UInt64 byte count,
//           base64-encoded. Exact, about a third of the size of the text, and fast to write: the
//           simulation snapshots use it. ParaView reads both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "common/vec3.hpp"

namespace rbcsim::io {

enum class VtkEncoding { ascii, base64 };

// The values of one array, component after component, tuple after tuple.
using DataArrayValues = std::variant<std::span<const double>, std::span<const std::int32_t>,
                                     std::span<const std::int64_t>, std::span<const std::uint8_t>>;

struct DataArray {
  std::string name;
  int component_count = 1;  // values per tuple (point): 1 for a scalar, 3 for a vector
  DataArrayValues values;

  std::size_t value_count() const;
};

// Kept under its historical name: the per-point arrays of a data set.
using PointDataArray = DataArray;

PointDataArray scalar_point_array(std::string name, std::span<const double> values);
PointDataArray vector_point_array(std::string name, std::span<const Vec3> values);
// A per-point flag or category, such as the lattice's solid mask.
PointDataArray byte_point_array(std::string name, std::span<const std::uint8_t> values);

// Throws std::invalid_argument unless every array has a plain-text name (no XML markup), 1 or 3
// components and one tuple per point.
void check_point_arrays(std::size_t point_count, std::span<const PointDataArray> arrays);

// The attributes every <VTKFile> element of rbcsim carries, whatever the encoding:
// byte_order="LittleEndian" header_type="UInt64".
std::string_view vtk_file_attributes();

// Writes <DataArray type=... Name=... [NumberOfComponents=...] format=...>values</DataArray>,
// each line starting with `indent`.
void write_data_array(std::ostream& out, const DataArray& array, VtkEncoding encoding,
                      std::string_view indent);

}  // namespace rbcsim::io
