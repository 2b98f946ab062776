// XDMF 3 time series (.xdmf) over HDF5 snapshots (parallel/hdf5_file.hpp): a temporal collection
// of grids, each naming its datasets in one .h5 file, which ParaView's XDMF reader opens as one
// animated data set, as it opens a .pvd of VTK files (pvd_collection.hpp). Two layouts:
//   image      the lattice's nodes, z slowest: datasets of shape {nz, ny, nx} or {nz, ny, nx, 3};
//   triangles  a surface: points {points, 3} and triangles {triangles, 3} (0-based point
//              indices) datasets, with per-point datasets {points} or {points, 3}.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace rbcsim::io {

enum class XdmfNumber { float64, int32, uint8 };

// A per-node or per-point dataset of each snapshot, shown under its dataset name.
struct XdmfArray {
  std::string name;
  std::size_t components = 1;  // 1: scalar, 3: vector
  XdmfNumber number = XdmfNumber::float64;
};

struct XdmfImage {
  std::array<std::size_t, 3> nodes{};  // x, y, z
  std::array<double, 3> origin{};      // x, y, z of node (0, 0, 0)
  double spacing = 1.0;
};

struct XdmfTriangles {
  std::size_t points = 0;
  std::size_t triangles = 0;
  std::string points_dataset;     // float64 {points, 3}
  std::string triangles_dataset;  // int32 {triangles, 3}
};

struct XdmfEntry {
  double time = 0.0;
  std::string file;  // the .h5 file, relative to the .xdmf
};

using XdmfLayout = std::variant<XdmfImage, XdmfTriangles>;

// Through write_file_atomically. Throws std::invalid_argument for a name or file that is empty or
// holds XML markup characters or a colon (the separator of file and dataset).
void write_xdmf_series(const std::filesystem::path& path, const XdmfLayout& layout,
                       std::span<const XdmfArray> arrays, std::span<const XdmfEntry> entries);

// The entries of a series written by write_xdmf_series, in file order, so a resumed run can
// continue it. Throws InputError naming the file if it is not such a series.
std::vector<XdmfEntry> read_xdmf_series(const std::filesystem::path& path);

}  // namespace rbcsim::io
