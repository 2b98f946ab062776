// What `rbcsim mesh info` reports about a triangle mesh, and what mesh import checks: counts,
// topology (closed, manifold, consistently oriented, components, genus), size and shape (area,
// volume, reduced volume, principal dimensions, bounding box), triangle quality (edge lengths,
// angles, degenerate and sliver triangles) and the reference sums of the paper's area-difference
// and total-curvature forces. Works on defective meshes too: what cannot be computed is empty.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "mesh/geometry.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

// A triangle is degenerate if its area is below this fraction of the squared mean edge length
// (zero up to float32 rounding of the coordinates), and a sliver if its smallest angle is below
// kSliverAngleDeg.
inline constexpr double kDegenerateAreaFraction = 1e-6;
inline constexpr double kSliverAngleDeg = 10.0;

struct EdgeConnectivity {
  std::size_t edge_count = 0;               // distinct undirected edges
  std::size_t boundary_edge_count = 0;      // with one triangle (holes)
  std::size_t non_manifold_edge_count = 0;  // with three or more triangles
  std::size_t misoriented_edge_count = 0;   // two triangles traversing it the same way
  std::size_t component_count = 0;          // triangles connected through shared vertices
};
EdgeConnectivity analyse_edges(const TriangleMesh& mesh);

struct MeshReport {
  std::size_t vertex_count = 0;
  std::size_t edge_count = 0;
  std::size_t triangle_count = 0;
  std::size_t component_count = 0;
  std::size_t boundary_edge_count = 0;
  std::size_t non_manifold_edge_count = 0;
  std::size_t misoriented_edge_count = 0;
  bool closed = false;            // no boundary edge
  bool manifold = false;          // no edge with more than two triangles
  bool oriented = false;          // closed, manifold and consistently oriented
  long euler_characteristic = 0;  // V - E + F
  // (2 C - chi) / 2 summed over the components; only for closed oriented manifolds.
  std::optional<long> genus;

  double area_um2 = 0.0;
  double volume_um3 = 0.0;  // signed: negative for an inside-out mesh
  double reduced_volume = 0.0;
  // Extents along the principal axes of the vertex cloud, in order of decreasing variance (for an
  // elongated or flat cell: largest extent first, the discocyte's thickness last).
  Vec3 principal_extents_um = Vec3::Zero();
  Vec3 bounding_box_min_um = Vec3::Zero();
  Vec3 bounding_box_max_um = Vec3::Zero();

  double edge_min_um = 0.0;
  double edge_mean_um = 0.0;
  double edge_max_um = 0.0;
  double edge_stddev_um = 0.0;
  double min_angle_deg = 0.0;  // over the non-degenerate triangles
  double max_angle_deg = 0.0;
  std::size_t degenerate_triangle_count = 0;
  std::size_t sliver_triangle_count = 0;

  // Sum of M_j = l_j theta_j / 2 and of |M_j| (paper Eqs. 12-14): DeltaA0 / (2 D0) and
  // C0 / (2 D0). Only for closed oriented manifolds.
  std::optional<CurvatureSums> curvature;
};

MeshReport inspect_mesh(const TriangleMesh& mesh);

nlohmann::json to_json(const MeshReport& report);
// A two-column table, one quantity per line, units in the labels.
std::string to_text(const MeshReport& report);

}  // namespace rbcsim::mesh
