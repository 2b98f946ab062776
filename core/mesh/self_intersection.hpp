// Does a closed triangulated surface pass through itself? Nothing in the membrane energies keeps
// two distant parts of a cell apart, so a minimisation can fold a cup's lip through its own wall;
// such a surface encloses no well-defined volume and is no cell. Triangles that share a vertex
// are never tested against each other; every other pair whose bounding boxes overlap (a uniform
// grid of cells about one mean edge wide finds them in linear time) is tested edge against
// triangle (Moeller & Trumbore 1997): two triangles in general position intersect exactly when
// an edge of one crosses the other.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

// The intersecting pairs of triangles (indices, first < second), in increasing order.
std::vector<std::pair<std::size_t, std::size_t>> self_intersections(const TriangleMesh& mesh);

}  // namespace rbcsim::mesh
