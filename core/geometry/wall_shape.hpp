// A wall geometry in physical units (um): the region the fluid may occupy.
//
// Frame shared by every built-in shape: the flow runs along +x and starts at x = 0; the
// cross-section is centred on the x axis (y = z = 0). Imported (STL) walls keep the mesh's own
// coordinates.
//
// Shapes are plain, immutable objects; the lattice solver never sees them, only the solid mask
// that voxelise() (voxelise.hpp) produces from them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "common/vec3.hpp"
#include "geometry/lattice_grid.hpp"

namespace rbcsim::geometry {

// The box that holds all the fluid, and the axes along which the fluid leaves that box (periodic,
// inflow or outflow directions: the lattice needs no wall layer there). Index 0 = x, 1 = y, 2 = z.
struct FluidBounds {
  Vec3 min_um = Vec3::Zero();
  Vec3 max_um = Vec3::Zero();
  std::array<bool, 3> open_axes{false, false, false};
};

class WallShape {
 public:
  virtual ~WallShape() = default;

  // True where the point lies in the fluid; never outside fluid_bounds() along a walled axis.
  virtual bool is_fluid(const Vec3& point_um) const = 0;
  virtual FluidBounds fluid_bounds() const = 0;
  // Radius of the lumen at axial position x, for shapes that are circular tubes along x.
  virtual std::optional<double> radius_at_um(double x_um) const;

  // Marks the nx nodes (i, j, k), i = 0..nx-1, of one x-row: solid_row[i] = kSolid or kFluid.
  // The default asks is_fluid() node by node; a shape with a faster whole-row test overrides it.
  virtual void classify_row(const LatticeGrid& grid, int j, int k,
                            std::span<std::uint8_t> solid_row) const;

 protected:
  WallShape() = default;
  WallShape(const WallShape&) = default;
  WallShape& operator=(const WallShape&) = default;
};

}  // namespace rbcsim::geometry
