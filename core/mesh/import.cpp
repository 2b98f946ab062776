#include "mesh/import.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

#include <unistd.h>

#include "common/errors.hpp"
#include "io/text_file.hpp"
#include "mesh/ascii_stl_syntax.hpp"
#include "mesh/geometry.hpp"
#include "mesh/inspection.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::mesh {
namespace {

// Triangle soup or indexed mesh as assimp gives it, node transforms applied.
void collect_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_transform,
                  TriangleMesh& out) {
  const aiMatrix4x4 transform = parent_transform * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto base = static_cast<std::int32_t>(out.positions_um.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.positions_um.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      // Points and lines (1-2 indices) are not part of a surface: skipped, reported if nothing
      // else is left.
      if (face.mNumIndices != 3) continue;
      out.triangles.push_back({base + static_cast<std::int32_t>(face.mIndices[0]),
                               base + static_cast<std::int32_t>(face.mIndices[1]),
                               base + static_cast<std::int32_t>(face.mIndices[2])});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collect_node(scene, *node.mChildren[c], transform, out);
  }
}

constexpr std::uintmax_t kBinaryStlHeaderBytes = 84;  // 80-byte header + uint32 count
constexpr std::uintmax_t kBinaryStlTriangleBytes = 50;

bool has_stl_extension(const std::filesystem::path& path) {
  auto extension = path.extension().string();
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".stl";
}

// The first 84 bytes (fewer if the file is shorter).
std::string read_head(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::string head(kBinaryStlHeaderBytes, '\0');
  stream.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(stream.gcount()));
  return head;
}

std::string megabytes(double bytes) { return std::to_string(std::llround(bytes / 1e6)) + " MB"; }

// How many triangles the file can hold at most: a binary STL's header count (checked against the
// file size, which must be exactly 84 + 50 n), else what a text format fits in its size. An ASCII
// STL starts with "solid"; a binary STL that starts so anyway is recognised by its exact size.
struct TriangleBound {
  std::uintmax_t count;
  bool exact;  // a binary STL's count; else an upper bound
};

TriangleBound triangle_bound(const std::filesystem::path& path, std::uintmax_t file_bytes) {
  const std::string name = path.string();
  const TriangleBound text_bound{file_bytes / kMinTextBytesPerTriangle, false};
  if (!has_stl_extension(path)) return text_bound;
  const auto head = read_head(path);
  const bool says_ascii = head.rfind("solid", 0) == 0;
  if (head.size() < kBinaryStlHeaderBytes) {
    if (says_ascii) return text_bound;
    throw InputError(name, "neither an ASCII STL (no 'solid' line) nor a binary STL (" +
                               std::to_string(file_bytes) + " bytes, at least 84 expected)");
  }
  std::uint32_t declared = 0;
  std::memcpy(&declared, head.data() + 80, sizeof declared);
  const auto expected_bytes = kBinaryStlHeaderBytes + kBinaryStlTriangleBytes * declared;
  if (expected_bytes == file_bytes) return {declared, true};
  if (says_ascii) return text_bound;
  throw InputError(name, std::string(file_bytes < expected_bytes ? "truncated " : "") +
                             "binary STL: the header declares " + std::to_string(declared) +
                             " triangles (" + std::to_string(expected_bytes) +
                             " bytes) but the file has " + std::to_string(file_bytes) + " bytes");
}

void check_triangle_limit(const std::string& name, std::uintmax_t triangles,
                          std::size_t max_triangles) {
  if (triangles > max_triangles) {
    throw InputError(name, std::to_string(triangles) + " triangles, more than the limit of " +
                               std::to_string(max_triangles) + " (mesh.max_triangles)");
  }
}

double available_memory_bytes() {
  return static_cast<double>(sysconf(_SC_AVPHYS_PAGES)) *
         static_cast<double>(sysconf(_SC_PAGESIZE));
}

// Refuses, before anything is allocated, a file that could not be read in the memory there is or
// that holds more triangles than allowed.
TriangleBound check_size(const std::filesystem::path& path, std::uintmax_t file_bytes,
                         std::size_t max_triangles) {
  const std::string name = path.string();
  const auto [triangles, exact] = triangle_bound(path, file_bytes);
  const double needed_bytes =
      static_cast<double>(triangles) * static_cast<double>(kImportBytesPerTriangle);
  const double available_bytes = available_memory_bytes();
  if (needed_bytes > available_bytes) {
    throw InputError(name, "too large: up to " + std::to_string(triangles) +
                               " triangles would need about " + megabytes(needed_bytes) +
                               " to read, more than the " + megabytes(available_bytes) +
                               " of available memory");
  }
  // A binary STL's count is exact (a text file's bound is not): checked before reading too.
  if (exact) check_triangle_limit(name, triangles, max_triangles);
  return {triangles, exact};
}

TriangleMesh read_with_assimp(const std::filesystem::path& path, std::size_t max_triangles) {
  const std::string name = path.string();
  io::require_regular_file(path);
  const auto file_bytes = std::filesystem::file_size(path);
  if (file_bytes == 0) throw InputError(name, "empty file");
  const auto bound = check_size(path, file_bytes, max_triangles);
  if (has_stl_extension(path) && !bound.exact) {
    check_ascii_stl_syntax(io::read_text_file(path), name);
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(name, aiProcess_Triangulate);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw InputError(name, std::string("not a readable mesh (") + importer.GetErrorString() + ")");
  }
  TriangleMesh soup;
  collect_node(*scene, *scene->mRootNode, aiMatrix4x4(), soup);
  if (soup.triangles.empty()) throw InputError(name, "contains no triangles");
  check_triangle_limit(name, soup.triangle_count(), max_triangles);
  return soup;
}

// Replaces vertex indices through `representative` and drops vertices no triangle uses, keeping
// the order of first use (deterministic numbering).
TriangleMesh reindex(const TriangleMesh& mesh, const std::vector<std::int32_t>& representative) {
  TriangleMesh welded;
  std::vector<std::int32_t> new_index(mesh.vertex_count(), -1);
  welded.triangles.reserve(mesh.triangle_count());
  for (const auto& t : mesh.triangles) {
    Triangle mapped;
    for (int k = 0; k < 3; ++k) {
      const auto v = representative[t[k]];
      if (new_index[v] < 0) {
        new_index[v] = static_cast<std::int32_t>(welded.positions_um.size());
        welded.positions_um.push_back(mesh.positions_um[v]);
      }
      mapped[k] = new_index[v];
    }
    welded.triangles.push_back(mapped);
  }
  return welded;
}

TriangleMesh weld_exact(const TriangleMesh& soup) {
  std::map<std::array<double, 3>, std::int32_t> first_at;
  std::vector<std::int32_t> representative(soup.vertex_count());
  for (std::size_t v = 0; v < soup.vertex_count(); ++v) {
    const auto& p = soup.positions_um[v];
    representative[v] =
        first_at.try_emplace({p.x(), p.y(), p.z()}, static_cast<std::int32_t>(v)).first->second;
  }
  return reindex(soup, representative);
}

double mean_side_length_um(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k)
      sum += (mesh.positions_um[t[(k + 1) % 3]] - mesh.positions_um[t[k]]).norm();
  }
  return sum / (3.0 * static_cast<double>(mesh.triangle_count()));
}

// Merges vertices within `tolerance_um` (union of all chains), found through a uniform grid of
// cell size tolerance: close vertices are in the same or a neighbouring cell.
TriangleMesh weld_within(const TriangleMesh& mesh, double tolerance_um) {
  const auto cell_of = [tolerance_um](const Vec3& p) {
    return std::array<long, 3>{std::lround(std::floor(p.x() / tolerance_um)),
                               std::lround(std::floor(p.y() / tolerance_um)),
                               std::lround(std::floor(p.z() / tolerance_um))};
  };
  std::map<std::array<long, 3>, std::vector<std::int32_t>> grid;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    grid[cell_of(mesh.positions_um[v])].push_back(static_cast<std::int32_t>(v));
  }
  std::vector<std::int32_t> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::int32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const auto cell = cell_of(mesh.positions_um[v]);
    for (long dx = -1; dx <= 1; ++dx) {
      for (long dy = -1; dy <= 1; ++dy) {
        for (long dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (found == grid.end()) continue;
          for (auto other : found->second) {
            if ((mesh.positions_um[other] - mesh.positions_um[v]).norm() <= tolerance_um) {
              const auto a = root(static_cast<std::int32_t>(v));
              const auto b = root(other);
              parent[std::max(a, b)] = std::min(a, b);
            }
          }
        }
      }
    }
  }
  std::vector<std::int32_t> representative(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    representative[v] = root(static_cast<std::int32_t>(v));
  return reindex(mesh, representative);
}

void check_finite(const TriangleMesh& mesh, const std::string& name) {
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (!mesh.positions_um[v].allFinite()) {
      throw InputError(name, "vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
    }
  }
}

void check_triangles(const TriangleMesh& mesh, const std::string& name) {
  const double mean_edge = mean_side_length_um(mesh);
  const double degenerate_area = kDegenerateAreaFraction * mean_edge * mean_edge;
  std::size_t degenerate = 0;
  std::size_t first_degenerate = 0;
  std::set<std::array<std::int32_t, 3>> seen;
  std::size_t duplicates = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& corners = mesh.triangles[t];
    const bool repeated =
        corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2];
    if (repeated || triangle_area_um2(mesh.positions_um, corners) <= degenerate_area) {
      if (degenerate++ == 0) first_degenerate = t;
    }
    auto sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(sorted).second) ++duplicates;
  }
  if (degenerate > 0) {
    throw InputError(name, std::to_string(degenerate) +
                               " degenerate (zero-area) triangle(s), the first is triangle " +
                               std::to_string(first_degenerate));
  }
  if (duplicates > 0) {
    throw InputError(name, std::to_string(duplicates) +
                               " duplicate triangle(s) (the same three vertices twice)");
  }
}

void check_topology(const TriangleMesh& mesh, const std::string& name) {
  const auto edges = analyse_edges(mesh);
  if (edges.boundary_edge_count > 0) {
    throw InputError(name, "open surface: " + std::to_string(edges.boundary_edge_count) +
                               " boundary edge(s) with a single triangle (holes)");
  }
  if (edges.non_manifold_edge_count > 0) {
    throw InputError(name, "not a 2-manifold: " + std::to_string(edges.non_manifold_edge_count) +
                               " edge(s) shared by more than two triangles");
  }
  if (edges.component_count > 1) {
    throw InputError(name, std::to_string(edges.component_count) +
                               " separate connected surfaces (expected one cell)");
  }
  if (edges.misoriented_edge_count > 0) {
    throw InputError(
        name, "inconsistent triangle orientation: " + std::to_string(edges.misoriented_edge_count) +
                  " edge(s) traversed in the same direction by both triangles");
  }
  const long euler = static_cast<long>(mesh.vertex_count()) - static_cast<long>(edges.edge_count) +
                     static_cast<long>(mesh.triangle_count());
  if (euler != 2) {
    throw InputError(name, "genus " + std::to_string((2 - euler) / 2) +
                               " surface (Euler characteristic " + std::to_string(euler) +
                               "); a cell must be a sphere-like genus-0 surface");
  }
}

void apply_options(TriangleMesh& mesh, const ImportOptions& options, const std::string& name) {
  if (options.target_area_um2 && options.target_volume_um3) {
    throw InputError(name, "scale to an area or to a volume, not both");
  }
  auto require_positive = [&name](double value, const char* what) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw InputError(name, std::string(what) + " must be positive, got " + std::to_string(value));
    }
  };
  if (options.target_area_um2) {
    require_positive(*options.target_area_um2, "target area");
    scale_to_area(mesh, *options.target_area_um2);
  }
  if (options.target_volume_um3) {
    require_positive(*options.target_volume_um3, "target volume");
    scale_to_volume(mesh, *options.target_volume_um3);
  }
  if (options.align) align_principal_axes(mesh);
  if (options.center) translate_centroid_to_origin(mesh);
}

}  // namespace

ImportedMesh import_mesh(const std::filesystem::path& path, const ImportOptions& options) {
  const std::string name = path.string();
  const auto soup = read_with_assimp(path, options.max_triangles);
  check_finite(soup, name);
  ImportedMesh imported;
  imported.mesh = weld_exact(soup);
  imported.mesh =
      weld_within(imported.mesh, kWeldToleranceFraction * mean_side_length_um(imported.mesh));
  check_triangles(imported.mesh, name);
  check_topology(imported.mesh, name);
  if (enclosed_volume_um3(imported.mesh) < 0.0) {
    for (auto& t : imported.mesh.triangles) std::swap(t[1], t[2]);
    imported.notices.push_back(name +
                               ": the surface was inside out (normals pointing inwards); "
                               "flipped all " +
                               std::to_string(imported.mesh.triangle_count()) + " triangles");
  }
  apply_options(imported.mesh, options, name);
  return imported;
}

}  // namespace rbcsim::mesh
