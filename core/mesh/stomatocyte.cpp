#include "mesh/stomatocyte.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.hpp"
#include "mesh/geometry.hpp"
#include "mesh/thick_shell.hpp"
#include "mesh/transform.hpp"

namespace rbcsim::mesh {
namespace {

SurfaceMap cup_map(const StomatocyteShape& shape, double midline_radius_um,
                   double relative_thickness) {
  const double half_angle = shape.cup_half_angle_deg * std::numbers::pi / 180.0;
  const double thickness_um = relative_thickness * midline_radius_um;
  // The cup opens towards +z: its bottom at the origin, the arc's centre at (0, Rm); the normal
  // points to the centre, so u_z > 0 maps to the inner (cavity) face.
  return thick_shell_map({
      .midline_um =
          [=](double sigma) {
            return Eigen::Vector2d(midline_radius_um * std::sin(half_angle * sigma),
                                   midline_radius_um * (1.0 - std::cos(half_angle * sigma)));
          },
      .normal =
          [=](double sigma) {
            return Eigen::Vector2d(-std::sin(half_angle * sigma), std::cos(half_angle * sigma));
          },
      .thickness_um = [=, rim = shape.rim_thickening](
                          double sigma2) { return thickness_um * (1.0 + rim * sigma2); },
  });
}

double continuum_reduced_volume(const StomatocyteShape& shape, double relative_thickness) {
  const auto measures = axisymmetric_area_volume(cup_map(shape, 1.0, relative_thickness));
  return reduced_volume(measures.area_um2, measures.volume_um3);
}

// The inner face must not cross itself: its offset (at most t0 (1 + rim_thickening)) stays
// below the midline's radius of curvature, with a margin for the rounded bottom of the cavity.
constexpr double kMaxRelativeOffset = 0.8;

double solve_relative_thickness(const StomatocyteShape& shape) {
  const double max_thickness = kMaxRelativeOffset / (1.0 + shape.rim_thickening);
  double thin = 1e-3;
  double thick = max_thickness;
  const double reachable = continuum_reduced_volume(shape, thick);
  if (!(shape.reduced_volume > continuum_reduced_volume(shape, thin) &&
        shape.reduced_volume < reachable)) {
    throw InputError("shape stomatocyte-II",
                     "reduced_volume " + std::to_string(shape.reduced_volume) +
                         " is not reachable with cup_half_angle_deg " +
                         std::to_string(shape.cup_half_angle_deg) + " and rim_thickening " +
                         std::to_string(shape.rim_thickening) + " (at most " +
                         std::to_string(reachable) + ")");
  }
  // v grows monotonically with the wall thickness; 60 halvings reach double precision.
  for (int halving = 0; halving < 60; ++halving) {
    const double middle = 0.5 * (thin + thick);
    (continuum_reduced_volume(shape, middle) < shape.reduced_volume ? thin : thick) = middle;
  }
  return 0.5 * (thin + thick);
}

void validate(const StomatocyteShape& shape) {
  auto require = [](bool ok, const std::string& problem) {
    if (!ok) throw InputError("shape stomatocyte-II", problem);
  };
  require(shape.membrane_area_um2 > 0.0, "membrane_area_um2 must be positive");
  require(shape.cup_half_angle_deg > 0.0 && shape.cup_half_angle_deg < 150.0,
          "cup_half_angle_deg must be in (0, 150): beyond, the rim closes the mouth");
  require(shape.rim_thickening > -0.5 && shape.rim_thickening <= 2.0,
          "rim_thickening must be in (-0.5, 2]");
}

}  // namespace

SurfaceMap stomatocyte_map(const StomatocyteShape& shape, double midline_radius_um) {
  validate(shape);
  return cup_map(shape, midline_radius_um, solve_relative_thickness(shape));
}

TriangleMesh stomatocyte_mesh(const StomatocyteShape& shape, int subdivisions) {
  auto mesh = mesh_surface(stomatocyte_map(shape), subdivisions, shape.relaxation);
  scale_to_area(mesh, shape.membrane_area_um2);
  return mesh;
}

}  // namespace rbcsim::mesh
