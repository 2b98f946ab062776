// The unit icosphere: an icosahedron whose triangles are split in four `subdivisions` times, with
// every new vertex pushed onto the unit sphere. Level N has 10*4^N + 2 vertices, 30*4^N edges and
// 20*4^N triangles (level 4: 2562 / 7680 / 5120, the paper's resolution). All cell shapes are
// mapped from it, so every generated cell has this near-uniform triangulation.
#pragma once

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

TriangleMesh unit_icosphere(int subdivisions);

// One level of the icosphere refinement: every triangle split into four, each new vertex the
// normalised midpoint of its edge. Applied to any mesh of the unit sphere with the connectivity of
// level N it yields the connectivity of level N + 1 (the generators relax level by level).
TriangleMesh subdivide_on_sphere(const TriangleMesh& coarse);

}  // namespace rbcsim::mesh
