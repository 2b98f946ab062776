// Helpers shared by the mesh tests: quality figures computed independently of inspection.cpp,
// small hand-made solids, and temporary directories for file fixtures.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh::testing {

// Regular octahedron, vertices at unit distance on the axes, triangles counter-clockwise seen
// from outside.
inline TriangleMesh octahedron() {
  TriangleMesh mesh;
  mesh.positions_um = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                       Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return mesh;
}

struct Quality {
  double min_angle_deg = 180.0;
  double max_angle_deg = 0.0;
  double edge_ratio = 0.0;  // longest / shortest triangle side
};

inline Quality quality(const TriangleMesh& mesh) {
  Quality q;
  double shortest = INFINITY, longest = 0.0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.positions_um[t[(k + 1) % 3]] - mesh.positions_um[t[k]];
      const Vec3 b = mesh.positions_um[t[(k + 2) % 3]] - mesh.positions_um[t[k]];
      const double angle = std::acos(a.normalized().dot(b.normalized())) * 180.0 / std::numbers::pi;
      q.min_angle_deg = std::min(q.min_angle_deg, angle);
      q.max_angle_deg = std::max(q.max_angle_deg, angle);
      shortest = std::min(shortest, a.norm());
      longest = std::max(longest, a.norm());
    }
  }
  q.edge_ratio = longest / shortest;
  return q;
}

// A fresh directory under the system temp dir, removed with the object.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::random_device entropy;
    path_ = std::filesystem::temp_directory_path() /
            ("rbcsim_test_" + std::to_string(entropy()) + std::to_string(entropy()));
    std::filesystem::create_directories(path_);
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& content) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace rbcsim::mesh::testing
