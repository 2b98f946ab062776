#include "mesh/inspection.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <numeric>
#include <sstream>

#include "mesh/topology.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::mesh {
namespace {

struct OrientedEdgeUse {
  std::int32_t low;
  std::int32_t high;
  bool forward;  // traversed low -> high
  bool operator<(const OrientedEdgeUse& other) const {
    return std::tie(low, high) < std::tie(other.low, other.high);
  }
};

std::size_t count_components(const TriangleMesh& mesh) {
  std::vector<std::int32_t> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::int32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : mesh.triangles) {
    parent[root(t[1])] = root(t[0]);
    parent[root(t[2])] = root(t[0]);
  }
  std::vector<bool> used(mesh.vertex_count(), false);
  for (const auto& t : mesh.triangles) {
    for (auto v : t) used[v] = true;
  }
  std::size_t components = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (used[v] && root(static_cast<std::int32_t>(v)) == static_cast<std::int32_t>(v)) {
      ++components;
    }
  }
  return components;
}

void add_quality(const TriangleMesh& mesh, MeshReport& report) {
  double sum = 0.0, sum_squares = 0.0;
  report.edge_min_um = std::numeric_limits<double>::infinity();
  std::size_t corner_edges = 0;
  // Every undirected edge is seen twice in a closed mesh; statistics over the triangle sides are
  // the same then, and still defined for an open mesh.
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const double length = (mesh.positions_um[t[(k + 1) % 3]] - mesh.positions_um[t[k]]).norm();
      report.edge_min_um = std::min(report.edge_min_um, length);
      report.edge_max_um = std::max(report.edge_max_um, length);
      sum += length;
      sum_squares += length * length;
      ++corner_edges;
    }
  }
  const double n = static_cast<double>(corner_edges);
  report.edge_mean_um = sum / n;
  report.edge_stddev_um =
      std::sqrt(std::max(0.0, sum_squares / n - report.edge_mean_um * report.edge_mean_um));

  const double degenerate_area =
      kDegenerateAreaFraction * report.edge_mean_um * report.edge_mean_um;
  report.min_angle_deg = 180.0;
  for (const auto& t : mesh.triangles) {
    if (triangle_area_um2(mesh.positions_um, t) <= degenerate_area) {
      ++report.degenerate_triangle_count;
      continue;
    }
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.positions_um[t[(k + 1) % 3]] - mesh.positions_um[t[k]];
      const Vec3 b = mesh.positions_um[t[(k + 2) % 3]] - mesh.positions_um[t[k]];
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / std::numbers::pi;
      smallest = std::min(smallest, angle);
      report.max_angle_deg = std::max(report.max_angle_deg, angle);
    }
    report.min_angle_deg = std::min(report.min_angle_deg, smallest);
    if (smallest < kSliverAngleDeg) ++report.sliver_triangle_count;
  }
}

void add_size(const TriangleMesh& mesh, MeshReport& report) {
  report.area_um2 = surface_area_um2(mesh);
  report.volume_um3 = enclosed_volume_um3(mesh);
  report.reduced_volume = reduced_volume(report.area_um2, std::abs(report.volume_um3));
  report.bounding_box_min_um = report.bounding_box_max_um = mesh.positions_um.front();
  for (const auto& p : mesh.positions_um) {
    report.bounding_box_min_um = report.bounding_box_min_um.cwiseMin(p);
    report.bounding_box_max_um = report.bounding_box_max_um.cwiseMax(p);
  }
  const Eigen::Matrix3d axes = principal_axes(mesh);
  for (int axis = 0; axis < 3; ++axis) {
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const auto& p : mesh.positions_um) {
      low = std::min(low, p.dot(axes.col(axis)));
      high = std::max(high, p.dot(axes.col(axis)));
    }
    report.principal_extents_um[axis] = high - low;
  }
}

}  // namespace

EdgeConnectivity analyse_edges(const TriangleMesh& mesh) {
  std::vector<OrientedEdgeUse> half_edges;
  half_edges.reserve(3 * mesh.triangle_count());
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const auto from = t[k];
      const auto to = t[(k + 1) % 3];
      half_edges.push_back({std::min(from, to), std::max(from, to), from < to});
    }
  }
  std::sort(half_edges.begin(), half_edges.end());
  EdgeConnectivity connectivity;
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t end = i + 1;
    while (end < half_edges.size() && !(half_edges[i] < half_edges[end])) ++end;
    ++connectivity.edge_count;
    if (end - i == 1) ++connectivity.boundary_edge_count;
    if (end - i > 2) ++connectivity.non_manifold_edge_count;
    if (end - i == 2 && half_edges[i].forward == half_edges[i + 1].forward) {
      ++connectivity.misoriented_edge_count;
    }
    i = end;
  }
  connectivity.component_count = count_components(mesh);
  return connectivity;
}

MeshReport inspect_mesh(const TriangleMesh& mesh) {
  MeshReport report;
  report.vertex_count = mesh.vertex_count();
  report.triangle_count = mesh.triangle_count();
  if (mesh.triangles.empty()) return report;
  const auto connectivity = analyse_edges(mesh);
  report.edge_count = connectivity.edge_count;
  report.component_count = connectivity.component_count;
  report.boundary_edge_count = connectivity.boundary_edge_count;
  report.non_manifold_edge_count = connectivity.non_manifold_edge_count;
  report.misoriented_edge_count = connectivity.misoriented_edge_count;
  report.closed = connectivity.boundary_edge_count == 0;
  report.manifold = connectivity.non_manifold_edge_count == 0;
  report.oriented = report.closed && report.manifold && connectivity.misoriented_edge_count == 0;
  report.euler_characteristic = static_cast<long>(report.vertex_count) -
                                static_cast<long>(report.edge_count) +
                                static_cast<long>(report.triangle_count);
  if (report.oriented) {
    report.genus =
        (2 * static_cast<long>(report.component_count) - report.euler_characteristic) / 2;
    report.curvature = curvature_sums(mesh.positions_um, MeshTopology::build(mesh));
  }
  add_size(mesh, report);
  add_quality(mesh, report);
  return report;
}

nlohmann::json to_json(const MeshReport& r) {
  auto vec = [](const Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json json = {
      {"counts",
       {{"vertices", r.vertex_count},
        {"edges", r.edge_count},
        {"triangles", r.triangle_count},
        {"components", r.component_count}}},
      {"topology",
       {{"closed", r.closed},
        {"manifold", r.manifold},
        {"consistently_oriented", r.oriented},
        {"boundary_edges", r.boundary_edge_count},
        {"non_manifold_edges", r.non_manifold_edge_count},
        {"misoriented_edges", r.misoriented_edge_count},
        {"euler_characteristic", r.euler_characteristic},
        {"genus", r.genus ? nlohmann::json(*r.genus) : nlohmann::json()}}},
      {"size",
       {{"area_um2", r.area_um2},
        {"volume_um3", r.volume_um3},
        {"reduced_volume", r.reduced_volume},
        {"principal_extents_um", vec(r.principal_extents_um)},
        {"bounding_box_min_um", vec(r.bounding_box_min_um)},
        {"bounding_box_max_um", vec(r.bounding_box_max_um)}}},
      {"quality",
       {{"edge_length_min_um", r.edge_min_um},
        {"edge_length_mean_um", r.edge_mean_um},
        {"edge_length_max_um", r.edge_max_um},
        {"edge_length_stddev_um", r.edge_stddev_um},
        {"min_angle_deg", r.min_angle_deg},
        {"max_angle_deg", r.max_angle_deg},
        {"degenerate_triangles", r.degenerate_triangle_count},
        {"sliver_triangles", r.sliver_triangle_count},
        {"sliver_min_angle_deg", kSliverAngleDeg}}},
  };
  json["reference_sums"] =
      r.curvature ? nlohmann::json{{"area_difference_DeltaA0_over_2D0_um", r.curvature->signed_um},
                                   {"total_curvature_C0_over_2D0_um", r.curvature->absolute_um}}
                  : nlohmann::json();
  return json;
}

std::string to_text(const MeshReport& r) {
  std::ostringstream out;
  out << std::setprecision(6);
  auto row = [&out](const std::string& label, const auto& value) {
    out << "  " << std::left << std::setw(32) << label << value << '\n';
  };
  auto numbers = [](std::initializer_list<double> values) {
    std::ostringstream text;
    text << std::setprecision(5);
    for (double value : values) text << (text.tellp() > 0 ? "  " : "") << value;
    return text.str();
  };
  auto triple = [&numbers](const Vec3& v) { return numbers({v.x(), v.y(), v.z()}); };
  auto yes_no = [](bool flag) { return flag ? "yes" : "no"; };
  row("vertices / edges / triangles", std::to_string(r.vertex_count) + " / " +
                                          std::to_string(r.edge_count) + " / " +
                                          std::to_string(r.triangle_count));
  row("connected components", r.component_count);
  row("closed (boundary edges)",
      std::string(yes_no(r.closed)) + " (" + std::to_string(r.boundary_edge_count) + ")");
  row("manifold (non-manifold edges)",
      std::string(yes_no(r.manifold)) + " (" + std::to_string(r.non_manifold_edge_count) + ")");
  row("consistently oriented", yes_no(r.oriented));
  row("genus", r.genus ? std::to_string(*r.genus) : std::string("-"));
  row("area [um^2]", r.area_um2);
  row("volume [um^3]", r.volume_um3);
  row("reduced volume", r.reduced_volume);
  row("principal extents [um]", triple(r.principal_extents_um));
  row("bounding box min [um]", triple(r.bounding_box_min_um));
  row("bounding box max [um]", triple(r.bounding_box_max_um));
  row("edge length min/mean/max [um]", numbers({r.edge_min_um, r.edge_mean_um, r.edge_max_um}));
  row("edge length stddev [um]", r.edge_stddev_um);
  row("triangle angle min/max [deg]", numbers({r.min_angle_deg, r.max_angle_deg}));
  row("degenerate triangles", r.degenerate_triangle_count);
  row("slivers (min angle < 10 deg)", r.sliver_triangle_count);
  if (r.curvature) {
    row("DeltaA0/(2 D0) = sum M_j [um]", r.curvature->signed_um);
    row("C0/(2 D0) = sum |M_j| [um]", r.curvature->absolute_um);
  }
  return out.str();
}

}  // namespace rbcsim::mesh
