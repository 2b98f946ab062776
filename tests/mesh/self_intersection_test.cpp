// Self-intersection: none on a convex polyhedron; found where one vertex is pushed through the
// opposite side; not reported for triangles that only share a vertex or an edge.
#include <gtest/gtest.h>

#include "mesh/icosphere.hpp"
#include "mesh/self_intersection.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::mesh::self_intersections;

TEST(SelfIntersection, ConvexSurfaceHasNone) {
  EXPECT_TRUE(self_intersections(rbcsim::mesh::unit_icosphere(3)).empty());
}

TEST(SelfIntersection, AVertexPushedThroughTheFarSideIsFound) {
  auto sphere = rbcsim::mesh::unit_icosphere(2);
  // The vertex farthest along +z goes to z = -1.5: its fan of triangles now spans the sphere
  // and crosses the far side's triangles.
  std::size_t top = 0;
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
    if (sphere.positions_um[v].z() > sphere.positions_um[top].z()) top = v;
  }
  sphere.positions_um[top] = Vec3(0.01, 0.02, -1.5);
  const auto pairs = self_intersections(sphere);
  EXPECT_FALSE(pairs.empty());
  for (const auto& [first, second] : pairs) EXPECT_LT(first, second);
}

TEST(SelfIntersection, TrianglesSharingAVertexAreNotTested) {
  // Two triangles of a bow tie share vertex 0 and lie in crossing planes through it.
  rbcsim::mesh::TriangleMesh bow_tie{
      {Vec3(0, 0, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(0.5, 0, -1), Vec3(0.5, 0, 1)},
      {{0, 1, 2}, {0, 3, 4}}};
  EXPECT_TRUE(self_intersections(bow_tie).empty());
  // The same crossing without the shared vertex is an intersection.
  bow_tie.positions_um.push_back(Vec3(-0.5, 0, 0));
  bow_tie.triangles[1] = {5, 3, 4};
  EXPECT_EQ(self_intersections(bow_tie).size(), 1u);
}

}  // namespace
