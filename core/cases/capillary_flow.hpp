// The fluid of the capillary experiment (docs/commands/capillary.md): a wall shape whose lumen runs
// along +x (a built-in capillary or an STL wall open along x), on a lattice with one inflow and one
// outflow layer, driven by a velocity inlet with a Poiseuille profile and a pressure outlet.
//
// Why a velocity inlet rather than periodic x with a body force: the paper prescribes the inlet
// velocity (§3.3: "given an initial velocity of 0.04 m/s at the inlet"), which fixes the flow
// rate exactly, and the cell leaves through the outlet instead of re-entering a constriction
// whose upstream flow it has disturbed. The cost is a short development length at each end,
// where the run stops before the cell arrives.
//
// Lattice: the grid of geometry::lattice_around (open along x, round(length / dx) slices covering
// the lumen) plus one layer before and one after. Those layers copy the cross-section of the
// first and last lumen slices (so an STL wall, solid beyond its ends, works as well as a built-in
// tube); their fluid nodes become the inlet (bounce-back with the node's Poiseuille velocity) and
// the outlet (anti-bounce-back at density 1). Both boundaries act half-way, so the inlet plane is
// the lumen's upstream end and the outlet plane its downstream end.
#pragma once

#include <memory>
#include <utility>

#include "geometry/lattice_grid.hpp"
#include "geometry/wall_shape.hpp"
#include "lattice/fluid_solver.hpp"

namespace rbcsim::cases {

struct CapillaryLattice {
  geometry::LatticeGrid grid_um;  // slice 0 = inlet layer, slice nx - 1 = outlet layer
  geometry::SolidMask solid_mask;
  double inlet_x_um = 0.0;  // the inlet and outlet planes
  double outlet_x_um = 0.0;
};

// Throws InputError for a shape that is not open along x or whose end slices hold no fluid.
CapillaryLattice capillary_lattice(const geometry::WallShape& shape, double dx_um);

// The solver with walls (their exact positions given as wall links, used by the interpolated
// wall rules), the inlet carrying mean_inlet_velocity_lu over its effective area, and the outlet;
// at rest, density 1.
std::unique_ptr<lattice::FluidSolver> capillary_fluid(const geometry::WallShape& shape,
                                                      const CapillaryLattice& lattice,
                                                      const lattice::FluidParameters& parameters,
                                                      double mean_inlet_velocity_lu);

// Diameter of the inlet: the shape's own radius where it has one (built-in tubes), else that of
// the circle with the first lumen slice's effective area.
double inlet_diameter_um(const geometry::WallShape& shape, const CapillaryLattice& lattice);

// Diameter of the throat: the smallest of the shape's own diameter over [start_um, end_um]
// (sampled every 1/1000 of it) where it has one, else of the effective diameter of the lumen
// slices there.
double throat_diameter_um(const geometry::WallShape& shape, const CapillaryLattice& lattice,
                          double start_um, double end_um);

// The narrow section [start, end] along x: a built-in capillary's constriction; for any other
// wall, the lumen slices whose effective area is below kNarrowAreaFraction of the smaller end
// slice's. Throws InputError naming `source` if no slice is that narrow.
inline constexpr double kNarrowAreaFraction = 0.98;
std::pair<double, double> narrow_section_um(const geometry::WallShape& shape,
                                            const CapillaryLattice& lattice,
                                            std::string_view source);

}  // namespace rbcsim::cases
