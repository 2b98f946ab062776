// A wall given as a closed triangulated surface (e.g. an imported STL: a tube with its ends
// capped, a block with a channel cut through it). Fluid = inside the surface.
//
// Inside test: a ray along +x through the point (one ray per lattice row, so a whole row is
// classified at once). Every triangle the ray crosses adds -sign(n_x) to the winding number
// (+1 entering, -1 leaving an outward-oriented surface); a point is fluid where the winding
// number of the crossings before it is nonzero.
// Rays that hit an edge or a vertex exactly (common: STL coordinates and lattice rows are often
// round numbers) are decided by simulation of simplicity, the exact form of "jitter": the ray is
// treated as displaced by (epsilon, epsilon^2) in (y, z), infinitesimally. The side of an edge is
// computed from its lower-numbered vertex first, so the two triangles sharing an edge always see
// exactly opposite signs and a ray is counted in exactly one of them: no double or missed
// crossing. Consequence: a node exactly on a face parallel to x is fluid on the low-y (or, for
// y-parallel faces, low-z) side of the body and solid on the high side, a half-open rule. Only
// rays within rounding distance (~1e-16 relative) of a vertex can still be misjudged.
// A node exactly on a face crossed by its row is fluid or solid, undetermined.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/wall_shape.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::geometry {

class StlWall final : public WallShape {
 public:
  // Throws rbcsim::InputError naming `source` if the surface is empty, open, non-manifold or not
  // consistently oriented (its orientation itself, outward or inward, does not matter).
  explicit StlWall(mesh::TriangleMesh wall_mesh, std::array<bool, 3> open_axes = {},
                   std::string_view source = "stl");

  bool is_fluid(const Vec3& point_um) const override;
  FluidBounds fluid_bounds() const override { return bounds_; }
  void classify_row(const LatticeGrid& grid, int j, int k,
                    std::span<std::uint8_t> solid_row) const override;

 private:
  struct Crossing {
    double x_um;
    int winding_step;
  };
  // The crossings of the ray {(t, y, z)}, sorted by x.
  void collect_crossings(double y_um, double z_um, std::vector<Crossing>& crossings) const;
  std::size_t bucket_of(double y_um, double z_um) const;
  void build_buckets();

  mesh::TriangleMesh mesh_;
  FluidBounds bounds_;
  // Triangles binned by their (y, z) bounding boxes on a uniform grid of buckets, so that a ray
  // only tests the triangles of its own bucket.
  double bucket_size_um_ = 1.0;
  int buckets_y_ = 1;
  int buckets_z_ = 1;
  std::vector<std::int32_t> bucket_offsets_;
  std::vector<std::int32_t> bucket_triangles_;
};

}  // namespace rbcsim::geometry
