// The cell a run starts from: the mesh named by mesh.file, or else the built-in shape of the
// configured morphology at mesh.subdivisions, with the mesh.<shape>.* generator parameters.
// Either way the returned mesh is the membrane's stress-free reference (DESIGN.md §3.4).
#pragma once

#include <string>
#include <vector>

#include "config/config.hpp"
#include "mesh/cell_shapes.hpp"

namespace rbcsim::setup {

mesh::CellShapeParameters cell_shape_parameters_from(const config::Config& config);

struct CellMesh {
  mesh::TriangleMesh mesh;
  std::string source;                // the file, or "built-in <shape> level N"
  std::vector<std::string> notices;  // repairs made on import, to tell the user
};

// Throws rbcsim::InputError for an unreadable or defective mesh file.
CellMesh cell_mesh_from(const config::Config& config);

}  // namespace rbcsim::setup
