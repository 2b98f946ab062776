// The inside indicator of a closed surface (ibm/inside_indicator.hpp): its volume, exact winding
// numbers for columns through edges and vertices, continuity under sub-spacing motion, and
// independence of the thread count.
#include "ibm/inside_indicator.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/topology.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::ibm::NodeBox;
using rbcsim::ibm::smoothed_heaviside;
using rbcsim::ibm::SurfaceIndicator;
using rbcsim::ibm::SurfaceTriangle;
using rbcsim::mesh::TriangleMesh;

// The icosphere of `level` stretched to semi-axes `radii` about `centre` (lattice units).
TriangleMesh ellipsoid(int level, const Vec3& radii, const Vec3& centre) {
  TriangleMesh mesh = rbcsim::mesh::unit_icosphere(level);
  for (Vec3& p : mesh.positions_um) p = centre + p.cwiseProduct(radii);
  return mesh;
}

std::span<const SurfaceTriangle> triangles_of(const TriangleMesh& mesh) { return mesh.triangles; }

double indicator_sum(const SurfaceIndicator& indicator) {
  double sum = 0.0;
  for (const double value : indicator.values()) sum += value;
  return sum;
}

// Node (x, y, z) -> value, for comparing fields whose boxes differ.
std::map<std::tuple<int, int, int>, double> by_node(const SurfaceIndicator& indicator) {
  std::map<std::tuple<int, int, int>, double> values;
  const NodeBox& box = indicator.box();
  std::size_t n = 0;
  for (int k = 0; k < box.count[2]; ++k) {
    for (int j = 0; j < box.count[1]; ++j) {
      for (int i = 0; i < box.count[0]; ++i) {
        values[{box.first[0] + i, box.first[1] + j, box.first[2] + k}] = indicator.values()[n++];
      }
    }
  }
  return values;
}

TEST(SmoothedHeaviside, IsOneHalfOnTheSurfaceAndSymmetric) {
  for (const double eps : {1.0, 1.5, 2.0}) {
    EXPECT_EQ(smoothed_heaviside(0.0, eps), 0.5);
    EXPECT_EQ(smoothed_heaviside(eps, eps), 1.0);
    EXPECT_EQ(smoothed_heaviside(-eps, eps), 0.0);
    EXPECT_EQ(smoothed_heaviside(3.0 * eps, eps), 1.0);
    for (const double d : {0.1, 0.37, 0.8, 0.99}) {
      EXPECT_NEAR(smoothed_heaviside(d * eps, eps) + smoothed_heaviside(-d * eps, eps), 1.0, 1e-15);
    }
    // Continuous at +-eps: the sine term vanishes there.
    EXPECT_NEAR(smoothed_heaviside(eps * (1.0 - 1e-9), eps), 1.0, 1e-8);
  }
}

// The smoothed indicator sums to the enclosed volume up to the curvature bias of a distance-based
// smoothing: the layer |d| < eps has more area outside than inside, so (Steiner's formula)
//   sum H - V = -2 M int_{-eps}^{eps} d (H - step) dd = 2 (1/6 - 1/pi^2) eps^2 M,
// M = sum_edges l theta / 2 the integrated mean curvature: 0.39 (eps/R)^2 of V for a sphere of
// radius R (0.6 % at eps = 1, R = 8). The sharp count of inside nodes has no bias.
TEST(InsideIndicator, SumsToTheEnclosedVolumePlusTheCurvatureBias) {
  struct Case {
    Vec3 radii;
    double eps;
    double tolerance;  // of sum H against V
  };
  for (const Case& c : {Case{{8.0, 8.0, 8.0}, 1.0, 0.008}, Case{{8.0, 7.0, 6.0}, 1.0, 0.01},
                        Case{{8.0, 8.0, 8.0}, 2.0, 0.03}}) {
    const TriangleMesh mesh = ellipsoid(4, c.radii, {20.3, 19.71, 20.45});
    const double volume = rbcsim::mesh::enclosed_volume_um3(mesh);
    const double mean_curvature =
        rbcsim::mesh::curvature_sums(mesh.positions_um, rbcsim::mesh::MeshTopology::build(mesh))
            .signed_um;
    const double bias = 2.0 * (1.0 / 6.0 - 1.0 / (std::numbers::pi * std::numbers::pi)) * c.eps *
                        c.eps * mean_curvature;
    SurfaceIndicator indicator;
    indicator.compute(mesh.positions_um, triangles_of(mesh), c.eps);
    const double smooth = indicator_sum(indicator);
    double sharp = 0.0;
    for (const auto winding : indicator.winding_numbers()) sharp += winding;
    std::printf(
        "radii (%.0f %.0f %.0f), eps %.1f: sum H / V - 1 = %+.4f (bias %+.4f), "
        "inside nodes / V - 1 = %+.4f\n",
        c.radii.x(), c.radii.y(), c.radii.z(), c.eps, smooth / volume - 1.0, bias / volume,
        sharp / volume - 1.0);
    EXPECT_NEAR(smooth / volume, 1.0, c.tolerance);
    EXPECT_NEAR(smooth / (volume + bias), 1.0, 0.001);
    EXPECT_NEAR(sharp / volume, 1.0, 0.005);
    for (const double value : indicator.values()) {
      ASSERT_GE(value, 0.0);
      ASSERT_LE(value, 1.0);
    }
  }
}

// Octahedron |x| + |y| + |z| <= 3 and cube [2, 6]^3 with every vertex on a node: many columns run
// exactly through vertices and along projected edges, and the cube's side faces are seen edge-on.
// Every winding number must be 0 or 1, 1 strictly inside, 0 strictly outside.
TEST(InsideIndicator, ColumnsThroughVerticesAndEdgesCountOnce) {
  TriangleMesh octahedron;
  const Vec3 c(10.0, 10.0, 10.0);
  octahedron.positions_um = {c + Vec3(3, 0, 0),  c + Vec3(-3, 0, 0), c + Vec3(0, 3, 0),
                             c + Vec3(0, -3, 0), c + Vec3(0, 0, 3),  c + Vec3(0, 0, -3)};
  octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                          {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  TriangleMesh cube;
  for (int v = 0; v < 8; ++v) {
    cube.positions_um.emplace_back(v & 1 ? 6.0 : 2.0, v & 2 ? 6.0 : 2.0, v & 4 ? 6.0 : 2.0);
  }
  cube.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  const auto inside_octahedron = [&](const Vec3& p) { return (p - c).lpNorm<1>() - 3.0; };
  const auto inside_cube = [](const Vec3& p) {
    return (p - Vec3(4.0, 4.0, 4.0)).lpNorm<Eigen::Infinity>() - 2.0;
  };
  for (const auto& [mesh, level] :
       {std::pair{octahedron, std::function<double(const Vec3&)>(inside_octahedron)},
        std::pair{cube, std::function<double(const Vec3&)>(inside_cube)}}) {
    ASSERT_GT(rbcsim::mesh::enclosed_volume_um3(mesh), 0.0);  // outward
    for (const bool reversed : {false, true}) {
      TriangleMesh oriented = mesh;
      if (reversed) {
        for (auto& triangle : oriented.triangles) std::swap(triangle[1], triangle[2]);
      }
      SurfaceIndicator indicator;
      indicator.compute(oriented.positions_um, triangles_of(oriented), 1.0);
      const NodeBox& box = indicator.box();
      std::size_t n = 0;
      int on_surface_inside = 0;
      for (int k = 0; k < box.count[2]; ++k) {
        for (int j = 0; j < box.count[1]; ++j) {
          for (int i = 0; i < box.count[0]; ++i, ++n) {
            const Vec3 p(box.first[0] + i, box.first[1] + j, box.first[2] + k);
            const int winding = indicator.winding_numbers()[n] * (reversed ? -1 : 1);
            ASSERT_TRUE(winding == 0 || winding == 1) << p.transpose() << ": " << winding;
            const double signed_level = level(p);
            if (signed_level < 0.0) {
              EXPECT_EQ(winding, 1) << p.transpose();
            } else if (signed_level > 0.0) {
              EXPECT_EQ(winding, 0) << p.transpose();
            }
            if (signed_level == 0.0) {
              on_surface_inside += winding;
              EXPECT_NEAR(indicator.values()[n], 0.5, 1e-12) << p.transpose();  // d = 0 either way
            }
          }
        }
      }
      std::printf("nodes on the surface counted inside: %d\n", on_surface_inside);
    }
  }
}

// Moving the surface by a hundredth of a spacing changes H by at most that over eps (the
// Heaviside's steepest slope is 1/eps): no node flickers between inside and outside.
TEST(InsideIndicator, ChangesContinuouslyUnderSubSpacingMotion) {
  const TriangleMesh mesh = ellipsoid(3, {7.0, 6.0, 5.0}, {15.0, 15.0, 15.0});
  const double eps = 1.0;
  SurfaceIndicator indicator;
  indicator.compute(mesh.positions_um, triangles_of(mesh), eps);
  auto previous = by_node(indicator);
  const Vec3 shift(0.0061, 0.0047, 0.0083);
  double largest_change = 0.0;
  for (int s = 1; s <= 200; ++s) {  // more than a spacing along each axis
    TriangleMesh moved = mesh;
    for (Vec3& p : moved.positions_um) p += s * shift;
    indicator.compute(moved.positions_um, triangles_of(moved), eps);
    auto current = by_node(indicator);
    for (const auto& [node, value] : current) {
      const auto before = previous.find(node);
      const double old_value = before == previous.end() ? 0.0 : before->second;
      largest_change = std::max(largest_change, std::abs(value - old_value));
    }
    for (const auto& [node, value] : previous) {
      if (!current.contains(node)) largest_change = std::max(largest_change, value);
    }
    previous = std::move(current);
  }
  std::printf("largest change of H per step of %.4f: %.5f\n", shift.norm(), largest_change);
  EXPECT_LE(largest_change, shift.norm() / eps * (1.0 + 1e-9));
  EXPECT_GT(largest_change, 0.5 * shift.norm() / eps);  // it does move
}

TEST(InsideIndicator, OneAndTwoThreadsAreBitIdentical) {
  const TriangleMesh mesh = ellipsoid(4, {8.0, 7.5, 6.0}, {-3.3, 12.1, 40.7});
  std::vector<std::vector<double>> fields;
  const int previous_threads = omp_get_max_threads();
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    SurfaceIndicator indicator;
    indicator.compute(mesh.positions_um, triangles_of(mesh), 1.5);
    ASSERT_GE(indicator.box().node_count(), 4096u);  // large enough to use threads
    fields.emplace_back(indicator.values().begin(), indicator.values().end());
  }
  omp_set_num_threads(previous_threads);
  EXPECT_TRUE(fields[0] == fields[1]);
}

TEST(InsideIndicator, GridNodesWrapAlongPeriodicAxesOnly) {
  const rbcsim::ibm::GridView grid{10, 8, 6, true, false, true};
  const NodeBox box{{-2, -1, 5}, {3, 3, 3}};
  std::size_t node = 0;
  ASSERT_TRUE(rbcsim::ibm::grid_node_of(grid, box, 0, 1, 1, node));  // (-2, 0, 6) -> (8, 0, 0)
  EXPECT_EQ(node, rbcsim::ibm::node_index(grid, 8, 0, 0));
  EXPECT_FALSE(rbcsim::ibm::grid_node_of(grid, box, 0, 0, 0, node));  // y = -1: no node
}

}  // namespace
