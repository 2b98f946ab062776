// Cells packed into a straight tube or a walled slab to a target hematocrit (docs/physics.md,
// "Suspensions"): force-biased shrink-then-grow packing of the true cell meshes as rigid bodies.
//
//   1. Every cell starts at a reduced scale (kStartScale of its size), at a seeded random place in
//      the lumen and a uniformly random orientation (or lined up along the axis:
//      PackingOrientation), and they are spread apart rigidly (below);
//   2. then, repeatedly: overlapping cells (two vertices of different cells closer than
//      cell_gap_um, the contact's range, across the space's periodic axes; a vertex closer than
//      wall_gap_um to a wall, or, for cells that grow in the flow, through the wall once grown)
//      push each other apart as rigid bodies, each moved along its net
//      push and turned by its net torque, a small fraction of the gap per iteration; once no
//      cell overlaps, all cells grow by kScaleStep, until they are full size and clear (or clear
//      at PackingSettings::scale, from which they grow to full size in the flow).
//
// The hematocrit reached is measured from the placed meshes' own volumes over the space's volume
// (the tube's pi R^2 L, the slab's gap x length x width). Cells that cannot be made to clear at
// full size within max_iterations are an error naming the scale and hematocrit reached, never a
// silently lower hematocrit.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "common/vec3.hpp"
#include "contact/cell_list.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

struct PackingTube {
  double radius_um = 0.0;
  double length_um = 0.0;  // periodic along x over [0, length); the axis at y = z = 0
};

// Between flat walls at y = -gap/2 and +gap/2, periodic along x over [0, length) and along z over
// [0, width): the gap of a wall-bounded shear flow (sheared_suspension.hpp).
struct PackingSlab {
  double gap_um = 0.0;
  double length_um = 0.0;
  double width_um = 0.0;
};

using PackingSpace = std::variant<PackingTube, PackingSlab>;

// How the cells start (suspension.packing_orientation).
//   random: each at a random place in the lumen, in a uniformly random orientation;
//   axial:  each with its symmetry axis (its mesh's z) along the tube's axis (a slab's x), spun
//   about it at
//           random, at one of N evenly spaced places along the axis (the cells in random order,
//           each jittered by up to a quarter of the spacing) and at a random distance and angle
//           off it. In a tube not much wider than a cell, randomly turned cells jam before they
//           reach full size (5 discocytes in a 10 x 30 um tube at H_T 0.3 stopped at 0.94 of
//           their size); lined up along the axis, as they flow in capillaries, they fit.
enum class PackingOrientation { random, axial };

struct PackingSettings {
  double cell_gap_um = 0.75;  // no two vertices of different cells closer
  double wall_gap_um = 0.5;   // no vertex closer to the wall (at `scale`; grown, none through it)
  unsigned seed = 1;
  std::size_t max_iterations = 40000;
  PackingOrientation orientation = PackingOrientation::random;
  // The size the cells are packed at, a fraction of their own (suspension.packing_scale): below 1
  // they grow to full size in the flow (coupling/cell_growth.hpp), to reach hematocrits that
  // cells at their resting size cannot be packed to.
  double scale = 1.0;
};

// The cells as placed: one vertex array per cell, in the order of `cell_prototypes`.
struct Packing {
  std::vector<std::vector<Vec3>> positions_um;
  // Sum of the cells' volumes at full size / (pi R^2 L): the hematocrit once grown.
  double hematocrit = 0.0;
  double scale = 1.0;  // of their size the cells are placed at (PackingSettings::scale)
  std::size_t iterations = 0;
};

inline constexpr double kStartScale = 0.4;
inline constexpr double kScaleStep = 0.01;

// Packs one cell per entry of `cell_prototypes` (an index into `prototypes`, the stress-free
// meshes). Throws InputError naming suspension.hematocrit when the cells cannot all be placed
// clear of each other and the walls, with the scale and hematocrit reached.
Packing pack_cells(std::span<const mesh::TriangleMesh> prototypes,
                   std::span<const std::size_t> cell_prototypes, const PackingSpace& space,
                   const PackingSettings& settings);
Packing pack_cells_in_tube(std::span<const mesh::TriangleMesh> prototypes,
                           std::span<const std::size_t> cell_prototypes, const PackingTube& tube,
                           const PackingSettings& settings);

// A cell placed by hand: its solid centroid at centre_um; its mesh turned first by spin_deg about
// its own z (right-handed), then so that its z points along `axis` (any length but 0).
struct CellPose {
  Vec3 centre_um = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double spin_deg = 0.0;
};

// Places one cell per entry of `cell_prototypes` at its pose (`poses`, as many). Throws
// InputError naming suspension.cells when a cell comes closer than settings.cell_gap_um to
// another (across the periodic axes) or to itself across a period, closer than wall_gap_um to a
// wall, or inside another cell; `iterations` is 0.
Packing place_cells(std::span<const mesh::TriangleMesh> prototypes,
                    std::span<const std::size_t> cell_prototypes, std::span<const CellPose> poses,
                    const PackingSpace& space, const PackingSettings& settings);
Packing place_cells_in_tube(std::span<const mesh::TriangleMesh> prototypes,
                            std::span<const std::size_t> cell_prototypes,
                            std::span<const CellPose> poses, const PackingTube& tube,
                            const PackingSettings& settings);

// Whether `point_um` lies inside the closed surface (its winding number, the solid angle the
// triangles subtend over 4 pi, rounds to 1): used to check that no packed cell pierces another.
bool surface_contains(std::span<const Vec3> positions_um, std::span<const mesh::Triangle> triangles,
                      const Vec3& point_um);

// For each cell, the first other cell (in index order) that one of its vertices lies inside, if
// any: two surfaces that passed through each other. Cell c's vertices are positions_um[c], its
// triangles triangles[c]; other cells are taken at their image nearest to c across the box's
// periodic axes. Thread-count independent.
std::vector<std::optional<std::size_t>> find_pierced_cells(
    std::span<const std::vector<Vec3>> positions_um,
    std::span<const std::span<const mesh::Triangle>> triangles, const contact::PeriodicBox& box);

}  // namespace rbcsim::cases
