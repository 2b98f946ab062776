// From a wall shape in um to the solid mask the lattice solver consumes (conventions of the grid
// and the mask: lattice_grid.hpp).
//
// A node is solid exactly when its position lies outside the fluid. Half-way bounce-back
// (docs/physics.md, "Fluid") then puts the effective wall halfway between each fluid node and its
// solid neighbour: the staircase of the faces of the cubes (side dx) centred on the fluid nodes,
// not the geometric surface. The two agree only where the surface falls halfway between two nodes
// (lattice_around arranges that for the plates of a channel whose gap is a multiple of dx);
// elsewhere they differ by up to dx / 2 along a lattice axis. wall_measures.hpp measures the
// effective section (area, radius, gap) that flow tests must compare with.
#pragma once

#include "geometry/lattice_grid.hpp"
#include "geometry/wall_shape.hpp"

namespace rbcsim::geometry {

// Solid mask of the nodes of `grid`: kSolid where shape.is_fluid(node) is false. Throws
// rbcsim::InputError for an invalid grid.
SolidMask voxelise(const WallShape& shape, const LatticeGrid& grid);

// The smallest node-centred grid of spacing dx_um around the shape's fluid box, centred on it:
//  - along a walled axis: ceil(extent / dx) nodes across the fluid plus `wall_layers` solid nodes
//    on each side (all beyond the box, hence solid). A channel whose gap is n dx thus gets n fluid
//    nodes and its plates lie exactly halfway between the last fluid and the first solid node;
//  - along an open axis (periodic, inflow/outflow): round(extent / dx) nodes (at least one), node
//    i covering [min + i dx, min + (i + 1) dx] when the extent is a multiple of dx.
// Throws rbcsim::InputError for dx_um <= 0, wall_layers < 1 or a grid above 10^6 nodes per axis.
LatticeGrid lattice_around(const WallShape& shape, double dx_um, int wall_layers = 1);

}  // namespace rbcsim::geometry
