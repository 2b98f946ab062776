// Test shapes for the membrane tests: a sphere and an ellipsoid mapped from the unit icosphere,
// and the shipped cell meshes of meshes/.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/icosphere.hpp"
#include "mesh/import.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::membrane_test {

using mesh::TriangleMesh;

// The model's forces (every term's array too) at positions_um, at rest.
inline membrane::MembraneForces forces_at(const membrane::MembraneModel& model,
                                          const std::vector<Vec3>& positions_um) {
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  model.compute(positions_um, workspace, forces);
  return forces;
}

inline TriangleMesh ellipsoid(int subdivisions, const Vec3& semi_axes_um) {
  auto mesh = mesh::unit_icosphere(subdivisions);
  for (auto& position : mesh.positions_um) position = position.cwiseProduct(semi_axes_um);
  return mesh;
}

inline TriangleMesh sphere(int subdivisions, double radius_um) {
  return ellipsoid(subdivisions, Vec3::Constant(radius_um));
}

// A shipped cell mesh, meshes/<shape>_n<level>.stl, read through the importer as a user's would be.
inline TriangleMesh shipped(const std::string& shape, int level) {
  return mesh::import_mesh(std::string(RBCSIM_SOURCE_DIR) + "/meshes/" + shape + "_n" +
                           std::to_string(level) + ".stl")
      .mesh;
}

// The Evans-Fung discocyte of the parametric generator (exactly axisymmetric), which the
// membrane tests' figures were measured on; the shipped (energy-minimised) cells are among the
// property-test shapes below.
inline TriangleMesh discocyte(int level) { return mesh::generate_cell("discocyte", level); }

struct NamedShape {
  std::string name;
  TriangleMesh mesh;
};

// The property-test shapes: a sphere and an ellipsoid (closed-form answers), and every shipped
// cell mesh at both levels. Their names are known without building a mesh, and each mesh is built
// on its first use: ctest runs every test in a process of its own, and parametrised tests are
// named and counted at start-up, where building all eight meshes cost each of test_membrane's 557
// processes 0.6 s under the sanitizers (a third of that stage's CPU time in December 2026).
struct ShapeRecipe {
  std::string name;
  std::function<TriangleMesh()> build;
};

inline const std::vector<ShapeRecipe>& property_test_recipes() {
  static const std::vector<ShapeRecipe> recipes = [] {
    std::vector<ShapeRecipe> list = {
        {"sphere3", [] { return sphere(3, 3.0); }},
        {"ellipsoid3", [] { return ellipsoid(3, Vec3(4.0, 3.0, 2.0)); }}};
    for (const std::string shape : {"discocyte", "stomatocyte_II", "echinocyte_III"}) {
      for (const int level : {3, 4}) {
        auto file_stem = shape;
        std::replace(file_stem.begin(), file_stem.end(), '_', '-');
        list.push_back({shape + std::to_string(level),
                        [file_stem, level] { return shipped(file_stem, level); }});
      }
    }
    return list;
  }();
  return recipes;
}

inline std::size_t property_test_shape_count() { return property_test_recipes().size(); }

inline const std::string& property_test_shape_name(std::size_t index) {
  return property_test_recipes().at(index).name;
}

// The index-th property-test shape, built on the first call and kept.
inline const NamedShape& property_test_shape(std::size_t index) {
  static std::vector<std::optional<NamedShape>> built(property_test_shape_count());
  auto& slot = built.at(index);
  if (!slot)
    slot = NamedShape{property_test_shape_name(index), property_test_recipes()[index].build()};
  return *slot;
}

inline double mean_edge_length_um(const TriangleMesh& mesh) {
  const auto topology = mesh::MeshTopology::build(mesh);
  double sum = 0.0;
  for (const auto& edge : topology.edges()) {
    sum += (mesh.positions_um[edge.vertex1] - mesh.positions_um[edge.vertex0]).norm();
  }
  return sum / static_cast<double>(topology.edge_count());
}

// Each vertex moved by a vector of uniformly random direction and a length uniform in
// [0, noise_um] (fixed seed).
inline std::vector<Vec3> with_noise(std::vector<Vec3> positions_um, double noise_um,
                                    std::uint32_t seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (auto& p : positions_um) {
    const Vec3 direction = rbcsim::random_vec3(gaussian, generator);
    p += noise_um * uniform(generator) * direction.normalized();
  }
  return positions_um;
}

// A small random deformation: an affine stretch (so that the cell-level measures V, DeltaA, C
// change at first order) plus vertex noise of 2 % of the mean edge (so that every element does).
inline std::vector<Vec3> small_deformation(const TriangleMesh& mesh, std::uint32_t seed) {
  const Vec3 stretch(1.01, 0.995, 0.99);
  std::vector<Vec3> positions = mesh.positions_um;
  for (auto& p : positions) p = p.cwiseProduct(stretch);
  return with_noise(std::move(positions), 0.02 * mean_edge_length_um(mesh), seed);
}

}  // namespace rbcsim::membrane_test
