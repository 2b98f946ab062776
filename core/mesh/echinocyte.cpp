#include "mesh/echinocyte.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.hpp"
#include "mesh/geometry.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::mesh {
namespace {

constexpr int kRepulsionSteps = 300;
// Beyond this many blend widths below zero the softplus is < e^-40: the spicule is not felt.
constexpr double kNegligibleBlendWidths = 40.0;

double softplus(double x) {
  return x > 0.0 ? x + std::log1p(std::exp(-x)) : std::log1p(std::exp(x));
}

void validate(const EchinocyteShape& shape) {
  auto require = [](bool ok, const std::string& problem) {
    if (!ok) throw InputError("shape echinocyte-III", problem);
  };
  require(shape.membrane_area_um2 > 0.0, "membrane_area_um2 must be positive");
  require(shape.spicule_count >= 0 && shape.spicule_count <= 200,
          "spicule_count must be in 0..200");
  require(shape.spicule_height_um > 0.0, "spicule_height_um must be positive");
  require(shape.spicule_tip_radius_um > 0.0, "spicule_tip_radius_um must be positive");
  require(shape.spicule_flank_angle_deg > 5.0 && shape.spicule_flank_angle_deg < 85.0,
          "spicule_flank_angle_deg must be in (5, 85)");
  require(shape.spicule_base_blend_um > 0.0, "spicule_base_blend_um must be positive");
}

}  // namespace

std::vector<Vec3> spicule_axes(int count) {
  std::vector<Vec3> axes;
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double ring = std::sqrt(1.0 - z * z);
    axes.emplace_back(ring * std::cos(i * golden_angle), ring * std::sin(i * golden_angle), z);
  }
  // Repulsion evens out the spiral's seam. The gain moves a point by a tenth of the mean spacing
  // when pushed by one neighbour at that spacing.
  const double spacing = std::sqrt(4.0 * std::numbers::pi / std::max(count, 1));
  const double gain = 0.1 * spacing * spacing * spacing;
  for (int iteration = 0; iteration < kRepulsionSteps; ++iteration) {
    auto moved = axes;
    for (int i = 0; i < count; ++i) {
      Vec3 push = Vec3::Zero();
      for (int j = 0; j < count; ++j) {
        const Vec3 apart = axes[i] - axes[j];
        if (j != i) push += apart / std::pow(apart.norm(), 3);
      }
      moved[i] = (axes[i] + gain * push).normalized();
    }
    axes = moved;
  }
  return axes;
}

SurfaceMap echinocyte_map(const EchinocyteShape& shape, double body_radius_um) {
  validate(shape);
  const double height = shape.spicule_height_um;
  const double slope = std::tan(shape.spicule_flank_angle_deg * std::numbers::pi / 180.0);
  const double blend = shape.spicule_base_blend_um;
  // Near the tip the radius is R_tip - (k R_body^2 / a) gamma^2 / 2 in the polar angle gamma, and
  // a polar curve r(gamma) with r' = 0 has curvature (r - r'') / r^2. Solving for a:
  const double tip_radius = body_radius_um + height;
  const double polar_second_derivative =
      tip_radius * tip_radius / shape.spicule_tip_radius_um - tip_radius;
  if (polar_second_derivative <= 0.0) {
    throw InputError("shape echinocyte-III",
                     "spicule_tip_radius_um must be smaller than the cell radius");
  }
  const double hyperbola_a = slope * body_radius_um * body_radius_um / polar_second_derivative;
  // Only spicules within reach matter: their cone reaches zero height at s0, and the blend dies
  // out kNegligibleBlendWidths * w / k further.
  const double reach_um =
      std::sqrt(std::pow(height / slope + hyperbola_a, 2) - hyperbola_a * hyperbola_a) +
      kNegligibleBlendWidths * blend / slope;
  const double reach_chord2 = std::pow(reach_um / body_radius_um, 2);
  return [=, axes = spicule_axes(shape.spicule_count)](const Vec3& u) {
    double radius = body_radius_um;
    for (const auto& axis : axes) {
      const double chord2 = (u - axis).squaredNorm();
      if (chord2 > reach_chord2) continue;
      const double s2 = body_radius_um * body_radius_um * chord2;
      const double cone =
          height - slope * (std::sqrt(s2 + hyperbola_a * hyperbola_a) - hyperbola_a);
      radius += blend * softplus(cone / blend);
    }
    return Vec3(radius * u);
  };
}

TriangleMesh echinocyte_mesh(const EchinocyteShape& shape, int subdivisions) {
  validate(shape);
  // Body radius by a fixed-point iteration on the mesh area: the spicules' extra area depends
  // only weakly on the body radius, so R^2 <- R^2 + (A_target - A) / (4 pi) converges in a few
  // steps. Each step starts from the previous relaxed parameters and needs only a short touch-up.
  double body_radius = std::sqrt(shape.membrane_area_um2 / (4.0 * std::numbers::pi));
  auto parameters = relaxed_parameter_icosphere(echinocyte_map(shape, body_radius), subdivisions,
                                                shape.relaxation);
  auto touch_up = shape.relaxation;
  touch_up.iterations /= 4;
  for (int iteration = 0; iteration < 2; ++iteration) {
    const double missing_area =
        shape.membrane_area_um2 -
        surface_area_um2(map_mesh(echinocyte_map(shape, body_radius), parameters));
    const double radius2 = body_radius * body_radius + missing_area / (4.0 * std::numbers::pi);
    if (radius2 <= 0.0) {
      throw InputError("shape echinocyte-III",
                       "the spicules alone need more than membrane_area_um2");
    }
    body_radius = std::sqrt(radius2);
    parameters =
        relax_parameter_mesh(echinocyte_map(shape, body_radius), std::move(parameters), touch_up);
  }
  auto mesh = map_mesh(echinocyte_map(shape, body_radius), std::move(parameters));
  scale_to_area(mesh, shape.membrane_area_um2);
  return mesh;
}

}  // namespace rbcsim::mesh
