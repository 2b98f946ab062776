#include "mesh/discocyte.hpp"

#include "mesh/thick_shell.hpp"

namespace rbcsim::mesh {

SurfaceMap discocyte_map(const DiscocyteShape& shape) {
  // A flat midline: the disc of radius R0 in the plane z = 0.
  return thick_shell_map({
      .midline_um =
          [radius = shape.radius_um](double sigma) { return Eigen::Vector2d(radius * sigma, 0.0); },
      .normal = [](double) { return Eigen::Vector2d(0.0, 1.0); },
      .thickness_um =
          [shape](double rho2) {
            return 0.5 * shape.radius_um * (shape.c0 + shape.c2 * rho2 + shape.c4 * rho2 * rho2);
          },
  });
}

TriangleMesh discocyte_mesh(const DiscocyteShape& shape, int subdivisions) {
  return mesh_surface(discocyte_map(shape), subdivisions, shape.relaxation);
}

double discocyte_area_um2(const DiscocyteShape& shape) {
  return axisymmetric_area_volume(discocyte_map(shape)).area_um2;
}

}  // namespace rbcsim::mesh
