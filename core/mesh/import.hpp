// Reading a cell surface from a file (STL binary/ASCII, OBJ, PLY, OFF, whatever assimp reads),
// with coordinates taken as micrometres. Loaded with no assimp post-processing beyond
// triangulating polygons, so that assimp hides no defect; we weld the vertices ourselves and check
// the result. Every defect is one InputError line "FILE: problem".
//
// Welding: first vertices at exactly the same position (an STL stores every triangle's corners
// separately), then vertices closer than kWeldToleranceFraction times the mean edge length
// (float round-off from exporters that wrote the same corner twice with different digits).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

inline constexpr double kWeldToleranceFraction = 1e-5;

struct ImportOptions {
  std::optional<double> target_area_um2;    // scale uniformly to this area
  std::optional<double> target_volume_um3;  // or to this enclosed volume (not both)
  bool center = false;                      // move the centroid of the enclosed solid to the origin
  bool align = false;                       // principal axes -> x (largest extent), y, z (smallest)
};

struct ImportedMesh {
  TriangleMesh mesh;
  // Repairs and facts the caller should tell the user ("flipped 5120 inside-out triangles").
  std::vector<std::string> notices;
};

// The checked, welded, outward-oriented closed genus-0 surface; throws rbcsim::InputError.
ImportedMesh import_mesh(const std::filesystem::path& path, const ImportOptions& options = {});

}  // namespace rbcsim::mesh
