// The piecewise-linear map of a triangulated surface over the unit sphere: parameter vertices map
// to their surface vertices, edge midpoints to edge midpoints, every direction to the point of
// the triangle a plain scan over all triangles finds; the relaxation over it keeps vertices on
// the surface.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "common/vec3.hpp"
#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/inspection.hpp"
#include "mesh/surface_map.hpp"

namespace {

namespace mesh = rbcsim::mesh;
using rbcsim::Vec3;

// The icosphere carried onto a lumpy ellipsoid, each vertex also pushed by a seeded random amount:
// a surface with no smooth formula behind its triangles.
mesh::TriangleMesh lumpy_surface(const mesh::TriangleMesh& sphere) {
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> draw(-0.02, 0.02);
  auto surface = sphere;
  for (auto& p : surface.positions_um) {
    p = Vec3(3.0 * p.x(), 2.0 * p.y(), 1.0 * p.z()) * (1.0 + 0.1 * p.x() * p.y()) +
        rbcsim::random_vec3(draw, generator);
  }
  return surface;
}

// The image of `direction` found by trying every triangle: the one whose cone holds it.
Vec3 scanned_image(const mesh::TriangleMesh& sphere, const mesh::TriangleMesh& surface,
                   const Vec3& direction) {
  for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
    const auto& tri = sphere.triangles[t];
    const Vec3& a = sphere.positions_um[tri[0]];
    const Vec3& b = sphere.positions_um[tri[1]];
    const Vec3& c = sphere.positions_um[tri[2]];
    const Vec3 w(direction.dot(b.cross(c)), direction.dot(c.cross(a)), direction.dot(a.cross(b)));
    if (w.minCoeff() < 0.0) continue;
    const Vec3 barycentric = w / w.sum();
    return barycentric[0] * surface.positions_um[tri[0]] +
           barycentric[1] * surface.positions_um[tri[1]] +
           barycentric[2] * surface.positions_um[tri[2]];
  }
  ADD_FAILURE() << "no triangle holds the direction";
  return Vec3::Zero();
}

TEST(PiecewiseLinearMap, VerticesAndEdgeMidpointsMapOntoTheSurfaces) {
  const auto sphere = mesh::unit_icosphere(3);
  const auto surface = lumpy_surface(sphere);
  const auto map = mesh::piecewise_linear_map(sphere, surface);
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
    EXPECT_LT((map(sphere.positions_um[v]) - surface.positions_um[v]).norm(), 1e-12);
  }
  // The ray through the normalised midpoint of a flat edge crosses it at its midpoint, so its
  // image is the midpoint of the surface's edge.
  for (const auto& tri : sphere.triangles) {
    const Vec3 direction = (sphere.positions_um[tri[0]] + sphere.positions_um[tri[1]]).normalized();
    const Vec3 expected = 0.5 * (surface.positions_um[tri[0]] + surface.positions_um[tri[1]]);
    EXPECT_LT((map(direction) - expected).norm(), 1e-12);
  }
}

TEST(PiecewiseLinearMap, EveryDirectionMapsAsAScanOfAllTrianglesSays) {
  const auto sphere = mesh::unit_icosphere(2);
  const auto surface = lumpy_surface(sphere);
  const auto map = mesh::piecewise_linear_map(sphere, surface);
  std::mt19937_64 generator(11);
  std::normal_distribution<double> gaussian;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 direction = Vec3(gaussian(generator), gaussian(generator), gaussian(generator)).normalized();
    EXPECT_LT((map(direction) - scanned_image(sphere, surface, direction)).norm(), 1e-12);
  }
}

TEST(PiecewiseLinearMap, MeshesOfAnotherConnectivityAreRefused) {
  const auto sphere = mesh::unit_icosphere(2);
  EXPECT_THROW(mesh::piecewise_linear_map(sphere, mesh::unit_icosphere(3)), std::invalid_argument);
  auto off_sphere = sphere;
  off_sphere.positions_um[0] *= 1.01;
  EXPECT_THROW(mesh::piecewise_linear_map(off_sphere, sphere), std::invalid_argument);
}

TEST(PiecewiseLinearMap, RelaxationOverItEvensTrianglesAndKeepsVerticesOnTheSurface) {
  // A sphere of radius 4 um whose vertices crowd towards +z: each parameter point pulled along
  // the sphere towards the pole before mapping.
  const auto sphere = mesh::unit_icosphere(3);
  auto crowded = sphere;
  for (auto& p : crowded.positions_um) p = 4.0 * (p + 0.6 * Vec3::UnitZ()).normalized();
  const auto map = mesh::piecewise_linear_map(sphere, crowded);
  mesh::RelaxationSettings relaxation;
  relaxation.iterations = 200;
  const auto relaxed = mesh::map_mesh(map, mesh::relax_parameter_mesh(map, sphere, relaxation));
  // On the crowded mesh's surface: no farther from the sphere than its flat triangles are
  // (their centres lie at most the largest sagitta l^2 / (8 R) inside it).
  const auto before = mesh::inspect_mesh(crowded);
  const double sagitta = before.edge_max_um * before.edge_max_um / (8.0 * 4.0);
  for (const auto& p : relaxed.positions_um) {
    EXPECT_LE(p.norm(), 4.0 + 1e-12);
    EXPECT_GE(p.norm(), 4.0 - 1.5 * sagitta);
  }
  const auto after = mesh::inspect_mesh(relaxed);
  EXPECT_LT(after.edge_stddev_um / after.edge_mean_um, 0.5 * before.edge_stddev_um / before.edge_mean_um);
  EXPECT_GT(after.min_angle_deg, before.min_angle_deg);
}

}  // namespace
