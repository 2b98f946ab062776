// The hematocrit profile across a tube (cases/suspension_profile.hpp): a sphere on the axis gives
// the analytic profile of a ball, the profile integrates to the cells' volume over the lumen's
// wherever along x (and across the period) the cells lie, and lines through a surface's vertices
// and edges (exact hits, silhouette corners) still cross every closed surface an even number of
// times.
#include "cases/suspension_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"

namespace rbcsim::cases {
namespace {

mesh::TriangleMesh sphere(int subdivisions, double radius_um, const Vec3& centre_um) {
  auto mesh = mesh::unit_icosphere(subdivisions);
  for (Vec3& p : mesh.positions_um) p = centre_um + radius_um * p;
  return mesh;
}

std::vector<double> profile_of(const std::vector<mesh::TriangleMesh>& cells,
                               const RadialProfileGrid& grid) {
  std::vector<std::vector<Vec3>> positions;
  std::vector<std::span<const mesh::Triangle>> triangles;
  for (const auto& cell : cells) {
    positions.push_back(cell.positions_um);
    triangles.emplace_back(cell.triangles);
  }
  return radial_volume_fraction(positions, triangles, grid);
}

// The mean over the ring r1 < r < r2 of a ball's chord 2 sqrt(a^2 - r^2), over the length L:
// (4/3) ((a^2 - r1^2)^1.5 - (a^2 - r2^2)^1.5) / ((r2^2 - r1^2) L), the bracket clipped at r = a.
double ball_ring_fraction(double a, double r1, double r2, double length) {
  const auto cap = [a](double r) { return r < a ? std::pow(a * a - r * r, 1.5) : 0.0; };
  return 4.0 / 3.0 * (cap(r1) - cap(r2)) / ((r2 * r2 - r1 * r1) * length);
}

TEST(SuspensionProfile, ASphereOnTheAxisGivesTheProfileOfABall) {
  const double a = 3.0;
  const RadialProfileGrid grid{5.0, 10.0, 5, 50};
  // 2562 vertices: the polyhedron's volume is 0.4 % below the ball's.
  const auto profile = profile_of({sphere(4, a, Vec3(4.0, 0.0, 0.0))}, grid);
  ASSERT_EQ(profile.size(), 5u);
  for (std::size_t ring = 0; ring < 5; ++ring) {
    const double r1 = static_cast<double>(ring);
    const double expected = ball_ring_fraction(a, r1, r1 + 1.0, grid.length_um);
    SCOPED_TRACE(ring);
    // Rings 0-2 lie inside the ball: the chord is smooth there (1 % covers the polyhedron and the
    // lines' sampling of the ring). Ring 3 holds the ball's edge, where the chord falls steeply
    // to 0 and the polyhedron's flat facets differ most from the ball. Ring 4 is empty.
    const double tolerance = ring < 3 ? 0.01 * expected : ring == 3 ? 0.05 * expected : 0.0;
    EXPECT_NEAR(profile[ring], expected, tolerance);
  }
}

TEST(SuspensionProfile, IntegratesToTheCellsVolumeOverTheLumen) {
  // Three spheres off the axis, one beyond the period (x > L) and one across x = 0: the length
  // inside a cell does not depend on where along x it lies.
  const RadialProfileGrid grid{5.0, 12.0, 10, 50};
  const std::vector<mesh::TriangleMesh> cells{sphere(3, 1.5, Vec3(3.0, 2.0, -1.0)),
                                              sphere(3, 2.0, Vec3(17.0, -1.0, 1.5)),
                                              sphere(3, 1.0, Vec3(0.2, 0.5, 3.2))};
  double volume_um3 = 0.0;
  for (const auto& cell : cells) volume_um3 += mesh::enclosed_volume_um3(cell);
  const auto profile = profile_of(cells, grid);
  double integrated_um3 = 0.0;
  for (std::size_t ring = 0; ring < profile.size(); ++ring) {
    const double r1 = 0.5 * static_cast<double>(ring);
    const double r2 = r1 + 0.5;
    integrated_um3 += profile[ring] * std::numbers::pi * (r2 * r2 - r1 * r1) * grid.length_um;
  }
  // The lines stand for their square of the cross-section (0.1 um): 1 % on these sizes.
  EXPECT_NEAR(integrated_um3, volume_um3, 0.01 * volume_um3);
}

TEST(SuspensionProfile, LinesThroughVerticesAndEdgesCrossEachSurfaceEvenly) {
  // Lines every 0.25 um (exact in binary); an octahedron whose six vertices and the projections of
  // its edges fall exactly on lines: the line through its centre meets the four faces around
  // each apex at their shared vertex, the lines through its silhouette corners graze it.
  const RadialProfileGrid grid{8.0, 4.0, 1, 32};
  const Vec3 centre(1.0, -0.125, -0.125);
  mesh::TriangleMesh octahedron;
  for (const Vec3& direction : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0),
                                Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    octahedron.positions_um.push_back(centre + direction);
  }
  // Outward normals: the x vertices (0, 1) with each neighbouring pair of y, z vertices.
  octahedron.triangles = {{0, 2, 4}, {0, 4, 3}, {0, 3, 5}, {0, 5, 2},
                          {1, 4, 2}, {1, 3, 4}, {1, 5, 3}, {1, 2, 5}};
  ASSERT_NEAR(mesh::enclosed_volume_um3(octahedron), 4.0 / 3.0, 1e-12);
  const auto profile = profile_of({octahedron}, grid);  // no odd crossing: no throw
  // The disc's lines, counted here: the profile times their number, their square and the length
  // is the volume the lines see, the octahedron's to the lines' resolution (a 0.25 um square).
  std::size_t lines = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      if (std::hypot((i + 0.5) * 0.25 - 8.0, (j + 0.5) * 0.25 - 8.0) < 8.0) ++lines;
    }
  }
  const double seen_um3 = profile[0] * static_cast<double>(lines) * 0.0625 * grid.length_um;
  EXPECT_NEAR(seen_um3, 4.0 / 3.0, 0.1);
}

TEST(SuspensionProfile, RefusesAGridWithAnEmptyRing) {
  EXPECT_THROW(profile_of({}, {5.0, 10.0, 30, 50}), std::invalid_argument);
  EXPECT_THROW(profile_of({}, {0.0, 10.0, 5, 50}), std::invalid_argument);
}

}  // namespace
}  // namespace rbcsim::cases
