#include "membrane/reference_state.hpp"

#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "membrane/cell_geometry.hpp"
#include "membrane/surface_energies.hpp"
#include "membrane/vertex_patch.hpp"

namespace rbcsim::membrane {
namespace {

constexpr const char* kSource = "stress-free mesh";

double mean_volume_gradient_um2(std::span<const mesh::Triangle> triangles,
                                std::span<const Vec3> area_vectors_um2, std::size_t vertex_count) {
  std::vector<Vec3> gradients(vertex_count, Vec3::Zero());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (auto corner : triangles[t]) gradients[corner] += area_vectors_um2[t] / 3.0;
  }
  double sum = 0.0;
  for (const auto& gradient : gradients) sum += gradient.norm();
  return sum / static_cast<double>(vertex_count);
}

}  // namespace

double mean_reference_edge_um(const ReferenceState& reference) {
  double sum = 0.0;
  for (double length : reference.edge_lengths_um) sum += length;
  return sum / static_cast<double>(reference.edge_lengths_um.size());
}

ReferenceState capture_reference_state(std::span<const Vec3> positions_um,
                                       std::span<const mesh::Triangle> triangles,
                                       const mesh::MeshTopology& topology) {
  CellGeometry geometry(triangles.size(), topology.edge_count());
  measure_cell_geometry(positions_um, triangles, topology, geometry);

  ReferenceState reference;
  reference.edge_lengths_um = geometry.edge_lengths_um;
  reference.dihedral_angles_rad = geometry.dihedral_angles_rad;
  reference.triangle_areas_um2.resize(triangles.size());
  reference.triangle_perimeters_um.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const double area_um2 = geometry.triangle_area_vectors_um2[t].norm();
    if (!(area_um2 > 0.0)) {
      throw InputError(kSource, "triangle " + std::to_string(t) +
                                    " has zero area; the membrane forces need non-degenerate "
                                    "reference triangles");
    }
    const auto& c = triangles[t];
    reference.triangle_areas_um2[t] = area_um2;
    reference.triangle_perimeters_um[t] = (positions_um[c[1]] - positions_um[c[0]]).norm() +
                                          (positions_um[c[2]] - positions_um[c[1]]).norm() +
                                          (positions_um[c[0]] - positions_um[c[2]]).norm();
  }
  if (!(geometry.volume_um3 > 0.0)) {
    throw InputError(kSource, "enclosed volume " + std::to_string(geometry.volume_um3) +
                                  " um^3 is not positive: triangles must be counter-clockwise "
                                  "seen from outside");
  }
  reference.volume_um3 = geometry.volume_um3;
  reference.area_um2 = geometry.area_um2;
  reference.mean_volume_gradient_um2 = mean_volume_gradient_um2(
      triangles, geometry.triangle_area_vectors_um2, topology.vertex_count());
  reference.signed_curvature_sum_um = geometry.signed_curvature_sum_um;
  reference.absolute_curvature_sum_um = geometry.absolute_curvature_sum_um;
  std::vector<Vec3> normals(topology.vertex_count());
  reference.vertex_offsets_um.resize(topology.vertex_count());
  measure_vertex_patches(positions_um, triangles, topology, normals, reference.vertex_offsets_um);
  reference.vertex_mean_curvatures_per_um.resize(topology.vertex_count());
  for (std::size_t v = 0; v < topology.vertex_count(); ++v) {
    reference.vertex_mean_curvatures_per_um[v] =
        integrated_mean_curvature_um(topology, reference.edge_lengths_um,
                                     reference.dihedral_angles_rad, v) /
        vertex_area_um2(topology, reference.triangle_areas_um2, v);
  }
  return reference;
}

ReferenceState scaled_reference(const ReferenceState& reference, double scale) {
  if (!(scale > 0.0)) {
    throw std::invalid_argument("scaled_reference: scale " + std::to_string(scale) +
                                " is not positive");
  }
  const auto times = [](std::vector<double> values, double factor) {
    for (double& value : values) value *= factor;
    return values;
  };
  const double area = scale * scale;
  ReferenceState scaled = reference;
  scaled.edge_lengths_um = times(reference.edge_lengths_um, scale);
  scaled.triangle_areas_um2 = times(reference.triangle_areas_um2, area);
  scaled.triangle_perimeters_um = times(reference.triangle_perimeters_um, scale);
  scaled.volume_um3 = reference.volume_um3 * area * scale;
  scaled.area_um2 = reference.area_um2 * area;
  scaled.mean_volume_gradient_um2 = reference.mean_volume_gradient_um2 * area;
  scaled.signed_curvature_sum_um = reference.signed_curvature_sum_um * scale;
  scaled.absolute_curvature_sum_um = reference.absolute_curvature_sum_um * scale;
  scaled.vertex_offsets_um = times(reference.vertex_offsets_um, scale);
  scaled.vertex_mean_curvatures_per_um =
      times(reference.vertex_mean_curvatures_per_um, 1.0 / scale);
  return scaled;
}

}  // namespace rbcsim::membrane
