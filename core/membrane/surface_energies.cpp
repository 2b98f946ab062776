#include "membrane/surface_energies.hpp"

#include <cmath>
#include <stdexcept>

#include "membrane/hinge.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::membrane {
namespace {

// Adds c_angle d(theta_e)/dx + c_length d(l_e)/dx to the four vertices of edge e's hinge.
void add_hinge_gradient(const SurfaceMeasures& measures, std::size_t e, double per_angle_pN_um,
                        double per_length_pN, std::span<Vec3> gradient_pN) {
  const auto& edge = measures.topology->edges()[e];
  const auto gradients = hinge_gradients(hinge_of(measures.positions_um, edge));
  const std::array<std::int32_t, 4> vertices{edge.vertex0, edge.vertex1, edge.wing0, edge.wing1};
  for (std::size_t k = 0; k < 4; ++k) {
    gradient_pN[static_cast<std::size_t>(vertices[k])] +=
        per_angle_pN_um * gradients.angle_per_um[k] + per_length_pN * gradients.length[k];
  }
}

void add_triangle_gradient(const SurfaceMeasures& measures, std::size_t t,
                           double per_area_pN_per_um, std::span<Vec3> gradient_pN) {
  const auto& triangle = measures.triangles[t];
  const auto gradients = triangle_area_gradients_um(measures.positions_um, triangle,
                                                    measures.geometry.triangle_area_vectors_um2[t]);
  for (std::size_t k = 0; k < 3; ++k) gradient_pN[triangle[k]] += per_area_pN_per_um * gradients[k];
}

}  // namespace

SurfaceMeasures::SurfaceMeasures(std::span<const mesh::Triangle> triangles_in,
                                 const mesh::MeshTopology& topology_in)
    : triangles(triangles_in),
      topology(&topology_in),
      geometry(triangles_in.size(), topology_in.edge_count()),
      triangle_areas_um2(triangles_in.size()),
      vertex_curvatures_um(topology_in.vertex_count()),
      vertex_areas_um2(topology_in.vertex_count()) {}

void SurfaceMeasures::measure_area_and_volume(std::span<const Vec3> positions) {
  positions_um = positions;
  area_um2 = 0.0;
  double volume_um3 = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& corners = triangles[t];
    geometry.triangle_area_vectors_um2[t] = mesh::triangle_area_vector(positions, corners);
    triangle_areas_um2[t] = geometry.triangle_area_vectors_um2[t].norm();
    area_um2 += triangle_areas_um2[t];
    const Vec3 centroid =
        (positions[corners[0]] + positions[corners[1]] + positions[corners[2]]) / 3.0;
    volume_um3 += geometry.triangle_area_vectors_um2[t].dot(centroid) / 3.0;
  }
  geometry.volume_um3 = volume_um3;
}

void SurfaceMeasures::measure(std::span<const Vec3> positions) {
  positions_um = positions;
  measure_cell_geometry(positions, triangles, *topology, geometry);
  area_um2 = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    triangle_areas_um2[t] = geometry.triangle_area_vectors_um2[t].norm();
    area_um2 += triangle_areas_um2[t];
  }
  for (std::size_t v = 0; v < vertex_areas_um2.size(); ++v) {
    vertex_areas_um2[v] = vertex_area_um2(*topology, triangle_areas_um2, v);
    vertex_curvatures_um[v] = integrated_mean_curvature_um(*topology, geometry.edge_lengths_um,
                                                           geometry.dihedral_angles_rad, v);
  }
}

double integrated_mean_curvature_um(const mesh::MeshTopology& topology,
                                    std::span<const double> edge_lengths_um,
                                    std::span<const double> dihedral_angles_rad,
                                    std::size_t vertex) {
  const auto& offsets = topology.vertex_edge_offsets();
  const auto& edges = topology.vertex_edges();
  double curvature_um = 0.0;
  for (auto slot = offsets[vertex]; slot < offsets[vertex + 1]; ++slot) {
    const auto e = static_cast<std::size_t>(edges[static_cast<std::size_t>(slot)]);
    curvature_um += edge_lengths_um[e] * dihedral_angles_rad[e];
  }
  return curvature_um / 4.0;
}

namespace {

// A third of the summed areas of `vertex`'s triangles, area_of(t) giving triangle t's, um^2.
template <class TriangleArea>
double third_of_ring_area_um2(const mesh::MeshTopology& topology, std::size_t vertex,
                              const TriangleArea& area_of) {
  const auto& offsets = topology.vertex_triangle_offsets();
  const auto& triangles = topology.vertex_triangles();
  double area_um2 = 0.0;
  for (auto slot = offsets[vertex]; slot < offsets[vertex + 1]; ++slot) {
    area_um2 += area_of(static_cast<std::size_t>(triangles[static_cast<std::size_t>(slot)]));
  }
  return area_um2 / 3.0;
}

}  // namespace

double vertex_area_um2(const mesh::MeshTopology& topology,
                       std::span<const double> triangle_areas_um2, std::size_t vertex) {
  return third_of_ring_area_um2(topology, vertex,
                                [&](std::size_t t) { return triangle_areas_um2[t]; });
}

double vertex_area_um2(const mesh::MeshTopology& topology,
                       std::span<const Vec3> triangle_area_vectors_um2, std::size_t vertex) {
  return third_of_ring_area_um2(topology, vertex,
                                [&](std::size_t t) { return triangle_area_vectors_um2[t].norm(); });
}

double HelfrichBending::add(const SurfaceMeasures& measures, std::span<Vec3> gradient_pN) const {
  const double kappa = parameters.bending_modulus_pN_um;
  const auto vertex_count = measures.vertex_areas_um2.size();
  // H_i = M_i / A_i; E = 2 kappa sum_i H_i^2 A_i.
  std::vector<double> mean_curvature_per_um(vertex_count);
  double energy = 0.0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    mean_curvature_per_um[v] = measures.vertex_curvatures_um[v] / measures.vertex_areas_um2[v];
    energy += 2.0 * kappa * mean_curvature_per_um[v] * measures.vertex_curvatures_um[v];
  }
  // dE/dM_i = 4 kappa H_i and dM_i/d(theta_e) = l_e / 4 for both ends of e.
  const auto& edges = measures.topology->edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double coefficient =
        kappa * (mean_curvature_per_um[static_cast<std::size_t>(edges[e].vertex0)] +
                 mean_curvature_per_um[static_cast<std::size_t>(edges[e].vertex1)]);
    add_hinge_gradient(measures, e, coefficient * measures.geometry.edge_lengths_um[e],
                       coefficient * measures.geometry.dihedral_angles_rad[e], gradient_pN);
  }
  // dE/dA_i = -2 kappa H_i^2 and dA_i/dA_t = 1/3 for the corners of t.
  for (std::size_t t = 0; t < measures.triangles.size(); ++t) {
    const auto& corners = measures.triangles[t];
    double squares = 0.0;
    for (const auto corner : corners) squares += std::pow(mean_curvature_per_um[corner], 2);
    add_triangle_gradient(measures, t, -2.0 * kappa * squares / 3.0, gradient_pN);
  }
  return energy;
}

double reduced_area_difference(double curvature_sum_um, double area_um2) {
  return curvature_sum_um /
         (4.0 * std::numbers::pi * std::sqrt(area_um2 / (4.0 * std::numbers::pi)));
}

double curvature_sum_for(double reduced_area_difference, double area_um2) {
  return reduced_area_difference * 4.0 * std::numbers::pi *
         std::sqrt(area_um2 / (4.0 * std::numbers::pi));
}

double AreaDifferenceElasticity::add(const SurfaceMeasures& measures,
                                     std::span<Vec3> gradient_pN) const {
  const double stiffness_pN_um =
      2.0 * std::numbers::pi * parameters.nonlocal_ratio * parameters.bending_modulus_pN_um;
  const double area = measures.area_um2;
  const double excess_um =
      measures.geometry.signed_curvature_sum_um - parameters.relaxed_curvature_sum_um;
  // E = (s / A)(M - M0)^2: dE/dM = 2 s (M - M0) / A, dM/d(theta_e) = l_e / 2, dE/dA = -E / A.
  const double per_curvature_pN = stiffness_pN_um * excess_um / area;
  const auto& lengths = measures.geometry.edge_lengths_um;
  const auto& angles = measures.geometry.dihedral_angles_rad;
  for (std::size_t e = 0; e < lengths.size(); ++e) {
    add_hinge_gradient(measures, e, per_curvature_pN * lengths[e], per_curvature_pN * angles[e],
                       gradient_pN);
  }
  const double energy = stiffness_pN_um * excess_um * excess_um / area;
  for (std::size_t t = 0; t < measures.triangles.size(); ++t) {
    add_triangle_gradient(measures, t, -energy / area, gradient_pN);
  }
  return energy;
}

SkeletonReference capture_skeleton_reference(std::span<const Vec3> positions_um,
                                             std::span<const mesh::Triangle> triangles) {
  SkeletonReference reference;
  reference.metrics_um2.reserve(triangles.size());
  reference.areas_um2.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& corners = triangles[t];
    const Vec3 e1 = positions_um[corners[1]] - positions_um[corners[0]];
    const Vec3 e2 = positions_um[corners[2]] - positions_um[corners[0]];
    const std::array<double, 3> metric{e1.dot(e1), e1.dot(e2), e2.dot(e2)};
    const double determinant = metric[0] * metric[2] - metric[1] * metric[1];
    if (!(determinant > 0.0)) {
      throw std::invalid_argument("capture_skeleton_reference: triangle " + std::to_string(t) +
                                  " is degenerate");
    }
    reference.metrics_um2.push_back(metric);
    reference.areas_um2.push_back(0.5 * std::sqrt(determinant));
  }
  return reference;
}

double SkeletonElasticity::add(const SurfaceMeasures& measures, std::span<Vec3> gradient_pN) const {
  const auto& p = parameters;
  double energy = 0.0;
  for (std::size_t t = 0; t < measures.triangles.size(); ++t) {
    const auto& corners = measures.triangles[t];
    const auto& [g11, g12, g22] = reference->metrics_um2[t];
    const double area0 = reference->areas_um2[t];
    const Vec3 e1 = measures.positions_um[corners[1]] - measures.positions_um[corners[0]];
    const Vec3 e2 = measures.positions_um[corners[2]] - measures.positions_um[corners[0]];
    const double norm = 1.0 / (4.0 * area0 * area0);  // 1 / det G
    const double trace = (e1.dot(e1) * g22 - 2.0 * e1.dot(e2) * g12 + e2.dot(e2) * g11) * norm;
    const double ratio = measures.triangle_areas_um2[t] / area0;  // lambda1 lambda2
    const double alpha = ratio - 1.0;
    const double beta = trace / (2.0 * ratio) - 1.0;
    energy +=
        area0 *
        (0.5 * p.area_modulus_pN_per_um *
             (alpha * alpha + p.a3 * alpha * alpha * alpha + p.a4 * alpha * alpha * alpha * alpha) +
         p.shear_modulus_pN_per_um * (beta + p.b1 * alpha * beta + p.b2 * beta * beta));
    const double w_alpha =
        0.5 * p.area_modulus_pN_per_um *
            (2.0 * alpha + 3.0 * p.a3 * alpha * alpha + 4.0 * p.a4 * alpha * alpha * alpha) +
        p.shear_modulus_pN_per_um * p.b1 * beta;
    const double w_beta = p.shear_modulus_pN_per_um * (1.0 + p.b1 * alpha + 2.0 * p.b2 * beta);
    // E_t = A0 w: dE/dA = w_alpha + w_beta d(beta)/dA and dE/d(trace) = A0 w_beta / (2 ratio).
    const double per_area = w_alpha - w_beta * trace / (2.0 * ratio * ratio);
    const double per_trace = area0 * w_beta / (2.0 * ratio);
    add_triangle_gradient(measures, t, per_area, gradient_pN);
    const Vec3 trace_1 = 2.0 * norm * (g22 * e1 - g12 * e2);
    const Vec3 trace_2 = 2.0 * norm * (g11 * e2 - g12 * e1);
    gradient_pN[corners[1]] += per_trace * trace_1;
    gradient_pN[corners[2]] += per_trace * trace_2;
    gradient_pN[corners[0]] -= per_trace * (trace_1 + trace_2);
  }
  return energy;
}

void area_gradient(const SurfaceMeasures& measures, std::span<Vec3> gradient_um) {
  std::fill(gradient_um.begin(), gradient_um.end(), Vec3::Zero());
  for (std::size_t t = 0; t < measures.triangles.size(); ++t) {
    add_triangle_gradient(measures, t, 1.0, gradient_um);
  }
}

void volume_gradient(const SurfaceMeasures& measures, std::span<Vec3> gradient_um2) {
  // dV/dx_i = (1/3) sum of i's triangles' area vectors (exact on a closed surface).
  std::fill(gradient_um2.begin(), gradient_um2.end(), Vec3::Zero());
  for (std::size_t t = 0; t < measures.triangles.size(); ++t) {
    const Vec3 share = measures.geometry.triangle_area_vectors_um2[t] / 3.0;
    for (const auto corner : measures.triangles[t]) gradient_um2[corner] += share;
  }
}

}  // namespace rbcsim::membrane
