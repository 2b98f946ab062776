// Cell shapes as smooth maps of the unit sphere onto the membrane surface, and their meshing.
//
// Every generated cell is the image of `unit_icosphere(N)` under such a map, so all shapes share
// the icosphere's connectivity (level 4: 2562 vertices, 5120 triangles). A plain map crowds the
// triangles where the surface is strongly curved or stretched (the discocyte's rim, the flanks of
// an echinocyte's spicules), so `mesh_surface` then relaxes the vertices *tangentially*: each
// vertex keeps a parameter point on the unit sphere and its position is always exactly
// surface(parameter), so the relaxed mesh still lies on the exact surface.
#pragma once

#include <functional>

#include "mesh/triangle_mesh.hpp"

namespace rbcsim::mesh {

// Unit direction u (|u| = 1) -> point of the membrane in um. Must be a smooth, orientation-
// preserving embedding of the sphere (outward on the sphere maps to outward on the cell).
using SurfaceMap = std::function<Vec3(const Vec3& unit_direction)>;

struct RelaxationSettings {
  // Passes of tangential area-weighted smoothing per refinement level (the icosahedron, then each
  // subdivision: coarse levels move vertices far cheaply, fine levels even out locally).
  // 0 = the plain map.
  int iterations = 100;
  // Fraction of the way to the target moved per pass (0 < step <= 1).
  double step_fraction = 0.8;
};

// unit_icosphere(subdivisions) with its vertices slid over the sphere so that their images under
// `surface` form near-uniform triangles; positions are the parameter points (|p| = 1).
TriangleMesh relaxed_parameter_icosphere(const SurfaceMap& surface, int subdivisions,
                                         const RelaxationSettings& relaxation);
// Further relaxation of a parameter mesh (e.g. after a small change of the surface).
TriangleMesh relax_parameter_mesh(const SurfaceMap& surface, TriangleMesh parameter_mesh,
                                  const RelaxationSettings& relaxation);
// The image of a parameter mesh: same triangles, positions surface(p).
TriangleMesh map_mesh(const SurfaceMap& surface, TriangleMesh parameter_mesh);

// The piecewise-linear map of a triangulated cell onto its own surface: `parameter_sphere` is a
// triangulation of the unit sphere (every vertex |p| = 1) with the connectivity of `surface`, and
// a direction u maps to the point of `surface`'s triangle whose spherical counterpart the ray
// through u crosses, at the same barycentric coordinates (central projection onto the flat
// parameter triangle). So parameter vertex i maps to surface vertex i, and the map is a
// homeomorphism onto the surface whenever `surface` is embedded. With relax_parameter_mesh it
// evens out the triangles of a mesh that has no smooth map (a shape minimised as a mesh) while
// every vertex stays on the mesh's surface. Throws std::invalid_argument for meshes of different
// connectivity or parameter vertices off the unit sphere.
SurfaceMap piecewise_linear_map(const TriangleMesh& parameter_sphere, const TriangleMesh& surface);

// map_mesh(surface, relaxed_parameter_icosphere(...)).
TriangleMesh mesh_surface(const SurfaceMap& surface, int subdivisions,
                          const RelaxationSettings& relaxation = {});

// Area and enclosed volume of a surface of revolution about z, by quadrature along the meridian
// u = (cos psi, 0, sin psi), psi in [-pi/2, pi/2]. Independent of any mesh: generators use it to
// size shapes and tests use it as the continuum reference.
struct AreaVolume {
  double area_um2 = 0.0;
  double volume_um3 = 0.0;
};
AreaVolume axisymmetric_area_volume(const SurfaceMap& surface);

}  // namespace rbcsim::mesh
