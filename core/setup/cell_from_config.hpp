// The cell a run starts from: the mesh named by mesh.file, or else the built-in shape of the
// configured morphology at mesh.subdivisions, with the mesh.<shape>.* generator parameters.
// Either way the returned mesh is the membrane's stress-free reference (DESIGN.md §3.4).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
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

// "Cell larger than the domain" (config::require_cell_fits_domain) for `cell` as placed, against
// a fluid domain of `domain_extent_um` per axis, with the reach of the delta kernel named
// `ibm_kernel` as clearance: InputError(what, ...) naming the axis and the sizes in um.
// Experiment commands call it before they make their run directory.
void require_cell_fits_domain(const mesh::TriangleMesh& cell, const Vec3& domain_extent_um,
                              double spacing_um, std::string_view ibm_kernel,
                              std::string_view what);

}  // namespace rbcsim::setup
