// What the lattice actually sees of a voxelised wall, for flow tests and inlet conditions.
// With half-way bounce-back every fluid node owns the cube of side dx centred on it
// (voxelise.hpp), so the effective fluid volume is (fluid nodes) * dx^3 and the effective area of
// an x-slice is (fluid nodes in it) * dx^2.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/lattice_grid.hpp"

namespace rbcsim::geometry {

// Every function checks that the mask has grid.node_count() entries (std::invalid_argument) and
// that slice and column indices lie in the grid (std::out_of_range).

std::size_t fluid_node_count(const SolidMask& solid_mask);
// Fluid nodes / all nodes, in [0, 1].
double fluid_volume_fraction(const SolidMask& solid_mask);

// Effective flow area of the x-slice i: its fluid nodes times dx^2.
double slice_fluid_area_um2(const SolidMask& solid_mask, const LatticeGrid& grid, int i);
// Effective radius of a voxelised circular section: the radius of the circle with the slice's
// effective area, sqrt(area / pi). For a staircase circle of radius R it differs from R by at
// most dx / sqrt(2) (a node within R - dx/sqrt(2) of the axis is fluid with its whole cell, a node
// beyond R + dx/sqrt(2) is not), and in practice by far less. Pipe-flow tests compare the
// analytic Poiseuille solution at this radius.
double effective_radius_um(const SolidMask& solid_mask, const LatticeGrid& grid, int i);
// Effective gap of a channel: the fluid nodes of the y-column (i, *, k) times dx. For plates
// placed halfway between nodes (lattice_around) it equals the geometric gap.
double effective_gap_um(const SolidMask& solid_mask, const LatticeGrid& grid, int i, int k);

// Poiseuille flow in a circular pipe of radius R: u(r) / U_mean = 2 (1 - (r/R)^2) for r < R,
// 0 beyond.
double poiseuille_velocity_ratio(double r_um, double radius_um);

// Inlet profile u / U_mean for the x-slice i, one value per (j, k) node at index j + ny * k:
// the Poiseuille profile about the centroid of the slice's fluid nodes, with R the slice's
// effective radius, 0 at solid nodes, then scaled by a factor 1 + O((dx/R)^2) so that its mean
// over the fluid nodes is exactly 1: the lattice inflow then carries exactly U_mean times the
// effective area. Independent of the lattice units: multiply by U_mean in lattice units.
// Throws rbcsim::InputError if the slice has no fluid node.
std::vector<double> poiseuille_inlet_profile(const SolidMask& solid_mask, const LatticeGrid& grid,
                                             int i);

}  // namespace rbcsim::geometry
