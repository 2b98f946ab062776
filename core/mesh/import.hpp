// Reading a cell surface from a file (STL binary/ASCII, OBJ, PLY, OFF, whatever assimp reads),
// with coordinates taken as micrometres. Loaded with no assimp post-processing beyond
// triangulating polygons, so that assimp hides no defect; we weld the vertices ourselves and check
// the result. Every defect is one InputError line "FILE: problem".
//
// Welding: first vertices at exactly the same position (an STL stores every triangle's corners
// separately), then vertices closer than kWeldToleranceFraction times the mean edge length
// (float round-off from exporters that wrote the same corner twice with different digits).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

inline constexpr double kWeldToleranceFraction = 1e-5;

// Size limits checked before anything is read (docs/architecture.md: a huge file is refused up
// front). A cell has thousands of triangles (the paper's: 5120); the level-6 built-in shape has
// 81920.
inline constexpr std::size_t kDefaultMaxTriangles = 2'000'000;
// Peak memory of an import per triangle: assimp's copy (corners, normals, faces), our triangle
// soup, the welding map and the welded mesh, rounded up.
inline constexpr std::size_t kImportBytesPerTriangle = 400;
// The fewest bytes a text format (ASCII STL, OBJ, PLY, OFF) spends per triangle ("3 a b c\n" plus
// its share of vertex lines): file size / this bounds the triangle count of a text file.
inline constexpr std::size_t kMinTextBytesPerTriangle = 16;

struct ImportOptions {
  std::optional<double> target_area_um2;    // scale uniformly to this area
  std::optional<double> target_volume_um3;  // or to this enclosed volume (not both)
  bool center = false;                      // move the centroid of the enclosed solid to the origin
  bool align = false;                       // principal axes -> x (largest extent), y, z (smallest)
  std::size_t max_triangles = kDefaultMaxTriangles;  // mesh.max_triangles
};

struct ImportedMesh {
  TriangleMesh mesh;
  // Repairs and facts the caller should tell the user ("flipped 5120 inside-out triangles").
  std::vector<std::string> notices;
};

// The checked, welded, outward-oriented closed genus-0 surface; throws rbcsim::InputError.
// Before reading, a binary STL's header count must agree with the file size, and the file must fit
// in the available memory (sysconf) and under options.max_triangles.
ImportedMesh import_mesh(const std::filesystem::path& path, const ImportOptions& options = {});

}  // namespace rbcsim::mesh
