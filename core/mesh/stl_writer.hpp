// Binary STL output: little-endian float32, the unit normal of each triangle, attribute 0.
// Deterministic (fixed header, triangles in mesh order), so shipped meshes can be compared.
#pragma once

#include <filesystem>
#include <ostream>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

void write_stl_binary(std::ostream& out, const TriangleMesh& mesh);
// Through io::write_file_atomically.
void write_stl_binary(const std::filesystem::path& path, const TriangleMesh& mesh);

// By extension: ".stl" (binary STL) or ".vtp" (VTK XML PolyData); anything else is an InputError.
// Commands check the format before the work that makes the mesh, so a minimisation of minutes
// does not end in a format error.
void require_mesh_file_format(const std::filesystem::path& path);
void write_mesh_file(const std::filesystem::path& path, const TriangleMesh& mesh);

}  // namespace rbcsim::mesh
