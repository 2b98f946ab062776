// The continuum membrane energies of membrane/surface_energies.hpp against finite differences of
// themselves (every gradient), and against closed-form values: the Helfrich energy of a sphere,
// 8 pi kappa at any radius; the ADE energy of a sphere; Lim's skeleton energy under a uniform
// dilation and a pure shear of its reference, whose principal stretches are known exactly.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "membrane/surface_energies.hpp"
#include "mesh/geometry.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/topology.hpp"
#include "test_shapes.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::mesh::MeshTopology;
using rbcsim::mesh::TriangleMesh;
namespace membrane = rbcsim::membrane;
namespace shapes = rbcsim::membrane_test;

using Energy = std::function<double(const membrane::SurfaceMeasures&, std::span<Vec3>)>;

// A mesh moved off any symmetric state: every vertex displaced by up to `amplitude_um` per axis.
std::vector<Vec3> jiggled(const TriangleMesh& mesh, double amplitude_um, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> draw(-amplitude_um, amplitude_um);
  auto positions = mesh.positions_um;
  for (auto& p : positions) p += rbcsim::random_vec3(draw, generator);
  return positions;
}

// Largest |analytic - central difference| over every coordinate of a sample of vertices,
// relative to the largest |gradient| component.
double gradient_error(const TriangleMesh& mesh, const std::vector<Vec3>& positions,
                      const Energy& energy) {
  const auto topology = MeshTopology::build(mesh);
  membrane::SurfaceMeasures measures(mesh.triangles, topology);
  auto evaluate = [&](const std::vector<Vec3>& at, std::vector<Vec3>* gradient) {
    measures.measure(at);
    std::vector<Vec3> scratch(at.size(), Vec3::Zero());
    const double value = energy(measures, scratch);
    if (gradient) *gradient = scratch;
    return value;
  };
  std::vector<Vec3> gradient;
  evaluate(positions, &gradient);
  double largest = 0.0;
  for (const auto& g : gradient) largest = std::max(largest, g.cwiseAbs().maxCoeff());
  double worst = 0.0;
  constexpr double kStep_um = 1e-6;
  for (std::size_t v = 0; v < positions.size(); v += 7) {
    for (int axis = 0; axis < 3; ++axis) {
      auto plus = positions;
      auto minus = positions;
      plus[v][axis] += kStep_um;
      minus[v][axis] -= kStep_um;
      const double difference =
          (evaluate(plus, nullptr) - evaluate(minus, nullptr)) / (2 * kStep_um);
      worst = std::max(worst, std::abs(difference - gradient[v][axis]));
    }
  }
  return worst / largest;
}

struct NamedEnergy {
  const char* name;
  Energy energy;
};

TEST(SurfaceEnergies, EveryGradientMatchesAFiniteDifferenceOfItsEnergy) {
  const auto cell = shapes::discocyte(3);
  // The skeleton's reference: an ellipsoid through the cell's vertex directions, so the skeleton
  // is strained everywhere.
  std::vector<Vec3> reference;
  for (const auto& p : cell.positions_um) {
    reference.push_back(p.normalized().cwiseProduct(Vec3(3.6, 3.6, 2.4)));
  }
  const auto skeleton = membrane::capture_skeleton_reference(reference, cell.triangles);
  membrane::AreaDifferenceParameters ade;
  ade.relaxed_curvature_sum_um = 30.0;  // far from the shape's, so the term pushes
  const std::vector<NamedEnergy> energies = {
      {"bending", [](const auto& m, auto g) { return membrane::HelfrichBending{}.add(m, g); }},
      {"area difference",
       [ade](const auto& m, auto g) { return membrane::AreaDifferenceElasticity{ade}.add(m, g); }},
      {"skeleton",
       [&skeleton](const auto& m, auto g) {
         return membrane::SkeletonElasticity{{}, &skeleton}.add(m, g);
       }},
      {"area",
       [](const auto& m, auto g) {
         std::vector<Vec3> gradient(g.size());
         membrane::area_gradient(m, gradient);
         for (std::size_t i = 0; i < g.size(); ++i) g[i] += gradient[i];
         return m.area_um2;
       }},
      {"volume",
       [](const auto& m, auto g) {
         std::vector<Vec3> gradient(g.size());
         membrane::volume_gradient(m, gradient);
         for (std::size_t i = 0; i < g.size(); ++i) g[i] += gradient[i];
         return m.geometry.volume_um3;
       }},
  };
  for (const unsigned seed : {1u, 2u}) {
    const auto positions = jiggled(cell, 0.05, seed);
    for (const auto& [name, energy] : energies) {
      SCOPED_TRACE(name);
      // Central differences of step 1e-6 um: truncation ~1e-12, round-off ~1e-16 / 1e-6 of the
      // energy; 1e-6 of the largest component is far above both and far below any wrong term.
      EXPECT_LT(gradient_error(cell, positions, energy), 1e-6);
    }
  }
}

TEST(SurfaceEnergies, HelfrichEnergyOfASphereIsEightPiKappaAtAnyRadius) {
  const membrane::HelfrichBending bending{{0.2}};
  for (const double radius_um : {1.0, 3.0}) {
    // Juelicher's scheme on the icosphere converges to the continuum from above; at level 4
    // (2562 vertices) it is within 1 % (Bian et al. 2020 report the same order for scheme B).
    const auto sphere = shapes::sphere(4, radius_um);
    const auto topology = MeshTopology::build(sphere);
    membrane::SurfaceMeasures measures(sphere.triangles, topology);
    measures.measure(sphere.positions_um);
    std::vector<Vec3> gradient(sphere.vertex_count(), Vec3::Zero());
    const double energy = bending.add(measures, gradient);
    EXPECT_NEAR(energy / (8.0 * std::numbers::pi * 0.2), 1.0, 0.01) << "radius " << radius_um;
  }
}

TEST(SurfaceEnergies, AreaDifferenceOfASphereFollowsItsReducedAreaDifference) {
  // A sphere has Delta a = 1 (integrated mean curvature 4 pi R, R_A = R); with Delta a0 = 0 the
  // energy is (2 pi alpha kappa / A) M^2 = 8 pi^2 alpha kappa, with Delta a0 = 1 it vanishes.
  const auto sphere = shapes::sphere(4, 3.0);
  const auto topology = MeshTopology::build(sphere);
  membrane::SurfaceMeasures measures(sphere.triangles, topology);
  measures.measure(sphere.positions_um);
  const double realised = membrane::reduced_area_difference(
      measures.geometry.signed_curvature_sum_um, measures.area_um2);
  EXPECT_NEAR(realised, 1.0, 0.01);  // the polyhedron's discretisation error, as for bending
  membrane::AreaDifferenceParameters parameters{0.2, 2.0 / std::numbers::pi, 0.0};
  std::vector<Vec3> gradient(sphere.vertex_count(), Vec3::Zero());
  const double expected =
      8.0 * std::numbers::pi * std::numbers::pi * (2.0 / std::numbers::pi) * 0.2;
  EXPECT_NEAR(membrane::AreaDifferenceElasticity{parameters}.add(measures, gradient) / expected,
              realised * realised, 1e-12);
  parameters.relaxed_curvature_sum_um = membrane::curvature_sum_for(realised, measures.area_um2);
  EXPECT_NEAR(membrane::AreaDifferenceElasticity{parameters}.add(measures, gradient), 0.0, 1e-12);
}

// Lim's energy density for principal stretches (l1, l2), per reference area.
double lim_density(const membrane::SkeletonParameters& p, double l1, double l2) {
  const double alpha = l1 * l2 - 1.0;
  const double beta = (l1 - l2) * (l1 - l2) / (2.0 * l1 * l2);
  return 0.5 * p.area_modulus_pN_per_um *
             (alpha * alpha + p.a3 * std::pow(alpha, 3) + p.a4 * std::pow(alpha, 4)) +
         p.shear_modulus_pN_per_um * (beta + p.b1 * alpha * beta + p.b2 * beta * beta);
}

double skeleton_energy(const TriangleMesh& reference, const std::vector<Vec3>& positions) {
  const auto topology = MeshTopology::build(reference);
  const auto skeleton =
      membrane::capture_skeleton_reference(reference.positions_um, reference.triangles);
  membrane::SurfaceMeasures measures(reference.triangles, topology);
  measures.measure(positions);
  std::vector<Vec3> gradient(positions.size(), Vec3::Zero());
  return membrane::SkeletonElasticity{{}, &skeleton}.add(measures, gradient);
}

// A flat closed surface: an n x n grid of the unit square as the top face (counter-clockwise
// seen from +z) and a copy of its interior vertices as the bottom face (reversed), sharing the
// boundary vertices. Every triangle lies in z = 0, so an in-plane affine map deforms each of them
// by the same deformation gradient.
TriangleMesh flat_pillow(int n) {
  TriangleMesh pillow;
  std::vector<std::vector<std::int32_t>> top(n + 1, std::vector<std::int32_t>(n + 1));
  std::vector<std::vector<std::int32_t>> bottom = top;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const Vec3 point(double(i) / n, double(j) / n, 0.0);
      top[i][j] = static_cast<std::int32_t>(pillow.positions_um.size());
      pillow.positions_um.push_back(point);
      const bool boundary = i == 0 || j == 0 || i == n || j == n;
      if (boundary) {
        bottom[i][j] = top[i][j];
      } else {
        bottom[i][j] = static_cast<std::int32_t>(pillow.positions_um.size());
        pillow.positions_um.push_back(point);
      }
    }
  }
  // Each cell is split along a diagonal through an interior vertex (a diagonal between two
  // boundary vertices would be shared by the top's and the bottom's triangles: four).
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (const auto* face : {&top, &bottom}) {
        const auto& v = *face;
        const bool reversed = face == &bottom;
        std::array<std::array<std::int32_t, 3>, 2> halves;
        if ((i == 0 && j == n - 1) || (i == n - 1 && j == 0)) {
          halves = {
              {{v[i][j], v[i + 1][j], v[i][j + 1]}, {v[i + 1][j], v[i + 1][j + 1], v[i][j + 1]}}};
        } else {
          halves = {
              {{v[i][j], v[i + 1][j], v[i + 1][j + 1]}, {v[i][j], v[i + 1][j + 1], v[i][j + 1]}}};
        }
        for (auto half : halves) {
          if (reversed) std::swap(half[1], half[2]);
          pillow.triangles.push_back(half);
        }
      }
    }
  }
  return pillow;
}

TEST(SurfaceEnergies, SkeletonEnergyOfKnownStretchesIsLimsDensityTimesTheArea) {
  const membrane::SkeletonParameters lim;
  // A uniform scaling by s of any reference: every triangle has l1 = l2 = s.
  const auto ellipsoid = shapes::ellipsoid(3, Vec3(4.0, 3.0, 2.0));
  const double area = rbcsim::mesh::surface_area_um2(ellipsoid);
  EXPECT_NEAR(skeleton_energy(ellipsoid, ellipsoid.positions_um), 0.0, 1e-12);
  for (const double s : {0.95, 1.1}) {
    std::vector<Vec3> scaled;
    for (const auto& p : ellipsoid.positions_um) scaled.push_back(s * p);
    EXPECT_NEAR(skeleton_energy(ellipsoid, scaled), area * lim_density(lim, s, s), 1e-9 * area);
  }
  // A pure shear x -> s x, y -> y / s of the flat pillow (both faces: area 2): l1 = s, l2 = 1/s,
  // so alpha = 0 and only mu (beta + b2 beta^2) remains; a stretch x -> s x: l1 = s, l2 = 1.
  const auto pillow = flat_pillow(4);
  for (const double s : {1.05, 1.3}) {
    std::vector<Vec3> sheared;
    std::vector<Vec3> stretched;
    for (const auto& p : pillow.positions_um) {
      sheared.emplace_back(s * p.x(), p.y() / s, 0.0);
      stretched.emplace_back(s * p.x(), p.y(), 0.0);
    }
    EXPECT_NEAR(skeleton_energy(pillow, sheared), 2.0 * lim_density(lim, s, 1.0 / s), 1e-12);
    EXPECT_NEAR(skeleton_energy(pillow, stretched), 2.0 * lim_density(lim, s, 1.0), 1e-12);
  }
}

}  // namespace
