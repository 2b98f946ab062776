#include "shapes/shape_analysis.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "membrane/surface_energies.hpp"
#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::shapes {
namespace {

// A cluster of axis crossings ends where consecutive heights along the axis differ by more.
constexpr double kCrossingGap_um = 0.3;
constexpr int kProfileSamples = 4000;

std::vector<double> mean_curvatures_per_um(const mesh::TriangleMesh& mesh) {
  const auto topology = mesh::MeshTopology::build(mesh);
  membrane::SurfaceMeasures measures(mesh.triangles, topology);
  measures.measure(mesh.positions_um);
  std::vector<double> curvatures(mesh.vertex_count());
  for (std::size_t v = 0; v < curvatures.size(); ++v) {
    curvatures[v] = measures.vertex_curvatures_um[v] / measures.vertex_areas_um2[v];
  }
  return curvatures;
}

// A cup's concave inner surface lies to one side of the solid centroid; a disc's two dimples
// balance. Beyond this offset of the concave area's centroid the axis points at it.
constexpr double kCupAxisOffset_um = 0.3;

// The frame of the shape's symmetry axis (solid centroid at the origin).
struct AxisFrame {
  Vec3 centre;
  Vec3 axis;
  double height(const Vec3& p) const { return (p - centre).dot(axis); }
  double radius(const Vec3& p) const {
    const Vec3 offset = p - centre;
    return (offset - offset.dot(axis) * axis).norm();
  }
};

// The principal axis whose variance is most unlike the other two's: a disc's or an elongated
// body's symmetry axis.
AxisFrame principal_axis_frame(const mesh::TriangleMesh& mesh) {
  const Vec3 centre = mesh::solid_centroid_um(mesh);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : mesh.positions_um) covariance += (p - centre) * (p - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const auto& values = solver.eigenvalues();  // increasing
  const int column = (values[1] - values[0]) > (values[2] - values[1]) ? 0 : 2;
  return {centre, solver.eigenvectors().col(column).normalized()};
}

// A cup's axis runs from the solid centroid towards the centroid of its concave (H < 0) surface,
// the cavity's lining; shapes without such an offset (discs, spheres) use the principal axis.
AxisFrame axis_frame(const mesh::TriangleMesh& mesh) {
  auto frame = principal_axis_frame(mesh);
  const auto topology = mesh::MeshTopology::build(mesh);
  membrane::SurfaceMeasures measures(mesh.triangles, topology);
  measures.measure(mesh.positions_um);
  Vec3 weighted = Vec3::Zero();
  double area = 0.0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (measures.vertex_curvatures_um[v] < 0.0) {
      weighted += measures.vertex_areas_um2[v] * mesh.positions_um[v];
      area += measures.vertex_areas_um2[v];
    }
  }
  if (area > 0.0) {
    const Vec3 offset = weighted / area - frame.centre;
    if (offset.norm() > kCupAxisOffset_um) frame.axis = offset.normalized();
  }
  return frame;
}

// Height of each vertex above the mean of its neighbours along its area-weighted normal, per mean
// neighbour distance.
std::vector<double> ring_heights_per_edge(const mesh::TriangleMesh& mesh,
                                          const mesh::MeshTopology& topology) {
  const auto& edge_offsets = topology.vertex_edge_offsets();
  const auto& vertex_edges = topology.vertex_edges();
  const auto& triangle_offsets = topology.vertex_triangle_offsets();
  const auto& vertex_triangles = topology.vertex_triangles();
  std::vector<double> heights(mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    Vec3 normal = Vec3::Zero();
    for (auto slot = triangle_offsets[v]; slot < triangle_offsets[v + 1]; ++slot) {
      normal +=
          mesh::triangle_area_vector(mesh.positions_um, mesh.triangles[vertex_triangles[slot]]);
    }
    Vec3 ring = Vec3::Zero();
    double distance = 0.0;
    const auto count = edge_offsets[v + 1] - edge_offsets[v];
    for (auto slot = edge_offsets[v]; slot < edge_offsets[v + 1]; ++slot) {
      const auto& edge = topology.edges()[static_cast<std::size_t>(vertex_edges[slot])];
      const auto other = static_cast<std::size_t>(
          edge.vertex0 == static_cast<std::int32_t>(v) ? edge.vertex1 : edge.vertex0);
      ring += mesh.positions_um[other];
      distance += (mesh.positions_um[other] - mesh.positions_um[v]).norm();
    }
    ring /= static_cast<double>(count);
    distance /= static_cast<double>(count);
    heights[v] = (mesh.positions_um[v] - ring).dot(normal.normalized()) / distance;
  }
  return heights;
}

}  // namespace

Spicules find_spicules(const mesh::TriangleMesh& mesh) {
  const Vec3 centre = mesh::solid_centroid_um(mesh);
  const auto curvatures = mean_curvatures_per_um(mesh);
  const auto ring_heights = ring_heights_per_edge(mesh, mesh::MeshTopology::build(mesh));
  const auto& positions = mesh.positions_um;
  const std::size_t count = positions.size();
  std::vector<double> radii(count);
  for (std::size_t i = 0; i < count; ++i) radii[i] = (positions[i] - centre).norm();

  Spicules spicules;
  for (std::size_t i = 0; i < count; ++i) {
    if (ring_heights[i] > kSpikeHeightPerEdge) spicules.spike_vertices.push_back(i);
  }
  double height_sum = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    if (curvatures[i] <= kSpiculeTipMeanCurvature_per_um || ring_heights[i] > kSpikeHeightPerEdge) {
      continue;
    }
    bool farthest = true;
    double base_sum = 0.0;
    std::size_t base_count = 0;
    for (std::size_t j = 0; j < count && farthest; ++j) {
      if (j == i) continue;
      const double distance = (positions[j] - positions[i]).norm();
      if (distance < kSpiculeNeighbourhoodRadius_um &&
          (radii[j] > radii[i] || (radii[j] == radii[i] && j < i))) {
        farthest = false;
      }
      if (distance >= kSpiculeBaseInner_um && distance <= kSpiculeBaseOuter_um) {
        base_sum += radii[j];
        ++base_count;
      }
    }
    if (!farthest || base_count == 0) continue;
    const double height = radii[i] - base_sum / static_cast<double>(base_count);
    if (height <= kSpiculeProminence_um) continue;
    spicules.tip_vertices.push_back(i);
    height_sum += height;
  }
  const auto& tips = spicules.tip_vertices;
  if (!tips.empty()) spicules.mean_height_um = height_sum / static_cast<double>(tips.size());
  if (tips.size() < 2) return spicules;
  std::vector<double> nearest(tips.size(), INFINITY);
  for (std::size_t a = 0; a < tips.size(); ++a) {
    for (std::size_t b = 0; b < tips.size(); ++b) {
      if (a != b) {
        nearest[a] = std::min(nearest[a], (positions[tips[a]] - positions[tips[b]]).norm());
      }
    }
  }
  double sum = 0.0;
  for (double d : nearest) sum += d;
  const double mean = sum / static_cast<double>(nearest.size());
  double squares = 0.0;
  for (double d : nearest) squares += (d - mean) * (d - mean);
  spicules.nearest_spacing_mean_um = mean;
  spicules.nearest_spacing_cv = std::sqrt(squares / static_cast<double>(nearest.size())) / mean;
  return spicules;
}

Invagination measure_invagination(const mesh::TriangleMesh& mesh) {
  const auto frame = axis_frame(mesh);
  std::vector<double> band;
  double lowest = INFINITY;
  double highest = -INFINITY;
  double widest = 0.0;
  for (const auto& p : mesh.positions_um) {
    const double z = frame.height(p);
    lowest = std::min(lowest, z);
    highest = std::max(highest, z);
    widest = std::max(widest, frame.radius(p));
    if (frame.radius(p) < kAxisBand_um) band.push_back(z);
  }
  Invagination result;
  result.diameter_um = 2.0 * widest;
  if (band.empty()) return result;
  std::sort(band.begin(), band.end());
  // The lowest and highest clusters of crossings: a disc's two dimples, a cup's outer and inner
  // bottom.
  double low_sum = band.front();
  std::size_t low_count = 1;
  while (low_count < band.size() && band[low_count] - band[low_count - 1] <= kCrossingGap_um) {
    low_sum += band[low_count++];
  }
  if (low_count == band.size()) return result;  // one crossing: the axis grazes the surface
  double high_sum = band.back();
  std::size_t high_count = 1;
  while (band[band.size() - 1 - high_count + 1] - band[band.size() - 1 - high_count] <=
         kCrossingGap_um) {
    high_sum += band[band.size() - 1 - high_count];
    ++high_count;
  }
  const double low = low_sum / static_cast<double>(low_count);
  const double high = high_sum / static_cast<double>(high_count);
  result.centre_thickness_um = high - low;
  result.depth_um = std::max(highest - high, low - lowest);
  result.depth_to_diameter = result.depth_um / result.diameter_um;
  result.cup_offset_um = std::abs(0.5 * (high + low) - 0.5 * (highest + lowest));
  return result;
}

ProfileDistance distance_from_evans_fung(const mesh::TriangleMesh& mesh,
                                         const mesh::DiscocyteShape& shape) {
  auto scaled = mesh;
  mesh::scale_to_area(scaled, mesh::discocyte_area_um2(shape));
  const auto frame = principal_axis_frame(scaled);
  // The profile (r, z(r)) sampled evenly in the angle phi, r = R0 sin(phi), dense at the rim.
  std::vector<Eigen::Vector2d> profile(kProfileSamples + 1);
  for (int k = 0; k <= kProfileSamples; ++k) {
    const double phi = 0.5 * std::numbers::pi * k / kProfileSamples;
    const double s = std::sin(phi);
    const double half_thickness = 0.5 * shape.radius_um * std::cos(phi) *
                                  (shape.c0 + shape.c2 * s * s + shape.c4 * s * s * s * s);
    profile[static_cast<std::size_t>(k)] = {shape.radius_um * s, half_thickness};
  }
  ProfileDistance result;
  double squares = 0.0;
  for (const auto& p : scaled.positions_um) {
    const Eigen::Vector2d point(frame.radius(p), std::abs(frame.height(p)));
    double nearest = INFINITY;
    for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
      const Eigen::Vector2d segment = profile[k + 1] - profile[k];
      const double t =
          std::clamp((point - profile[k]).dot(segment) / segment.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (point - (profile[k] + t * segment)).norm());
    }
    result.max_um = std::max(result.max_um, nearest);
    squares += nearest * nearest;
  }
  result.rms_um = std::sqrt(squares / static_cast<double>(scaled.vertex_count()));
  return result;
}

}  // namespace rbcsim::shapes
