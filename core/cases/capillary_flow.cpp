#include "cases/capillary_flow.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/errors.hpp"
#include "geometry/capillary_wall.hpp"
#include "geometry/voxelise.hpp"
#include "geometry/wall_links.hpp"
#include "geometry/wall_measures.hpp"

namespace rbcsim::cases {
namespace {

void copy_slice(geometry::SolidMask& mask, const geometry::LatticeGrid& grid, int from, int to) {
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) mask[grid.index(to, j, k)] = mask[grid.index(from, j, k)];
  }
}

void require_fluid_slice(const CapillaryLattice& lattice, int i, const char* end) {
  if (geometry::slice_fluid_area_um2(lattice.solid_mask, lattice.grid_um, i) <= 0.0) {
    throw InputError("capillary wall", std::string("no fluid at the ") + end + " of the lumen");
  }
}

}  // namespace

CapillaryLattice capillary_lattice(const geometry::WallShape& shape, double dx_um) {
  if (!shape.fluid_bounds().open_axes[0]) {
    throw InputError("capillary wall", "the lumen must be open along x (the flow direction)");
  }
  CapillaryLattice lattice;
  lattice.grid_um = geometry::lattice_around(shape, dx_um);
  lattice.grid_um.nx += 2;
  lattice.grid_um.origin_um.x() -= dx_um;
  const auto& grid = lattice.grid_um;
  lattice.solid_mask = geometry::voxelise(shape, grid);
  copy_slice(lattice.solid_mask, grid, 1, 0);
  copy_slice(lattice.solid_mask, grid, grid.nx - 2, grid.nx - 1);
  lattice.inlet_x_um = grid.origin_um.x() + 0.5 * dx_um;
  lattice.outlet_x_um = grid.origin_um.x() + (grid.nx - 1.5) * dx_um;
  require_fluid_slice(lattice, 0, "inlet");
  require_fluid_slice(lattice, grid.nx - 1, "outlet");
  return lattice;
}

std::unique_ptr<lattice::FluidSolver> capillary_fluid(const geometry::WallShape& shape,
                                                      const CapillaryLattice& lattice,
                                                      const lattice::FluidParameters& parameters,
                                                      double mean_inlet_velocity_lu) {
  const auto& grid = lattice.grid_um;
  auto solver = std::make_unique<lattice::FluidSolver>(
      lattice::LatticeGrid(grid.nx, grid.ny, grid.nz), parameters);
  const auto inlet_profile = geometry::poiseuille_inlet_profile(lattice.solid_mask, grid, 0);
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        const std::size_t node = grid.index(i, j, k);
        if (lattice.solid_mask[node] == geometry::kSolid) {
          solver->set_wall(node);
        } else if (i == 0) {
          const double profile = inlet_profile[static_cast<std::size_t>(j + grid.ny * k)];
          solver->set_velocity_inlet(node, {mean_inlet_velocity_lu * profile, 0.0, 0.0});
        } else if (i == grid.nx - 1) {
          solver->set_pressure_outlet(node, 1.0);
        }
      }
    }
  }
  solver->set_wall_links(geometry::wall_link_fractions(shape, grid, lattice.solid_mask));
  return solver;
}

double inlet_diameter_um(const geometry::WallShape& shape, const CapillaryLattice& lattice) {
  if (const auto radius_um = shape.radius_at_um(lattice.inlet_x_um)) return 2.0 * *radius_um;
  return 2.0 * geometry::effective_radius_um(lattice.solid_mask, lattice.grid_um, 1);
}

double throat_diameter_um(const geometry::WallShape& shape, const CapillaryLattice& lattice,
                          double start_um, double end_um) {
  constexpr int kSamples = 1000;
  double smallest_um = INFINITY;
  if (shape.radius_at_um(start_um)) {
    for (int k = 0; k <= kSamples; ++k) {
      const double x_um = start_um + (end_um - start_um) * k / kSamples;
      if (const auto radius_um = shape.radius_at_um(x_um)) {
        smallest_um = std::min(smallest_um, 2.0 * *radius_um);
      }
    }
    return smallest_um;
  }
  const auto& grid = lattice.grid_um;
  for (int i = 1; i < grid.nx - 1; ++i) {
    const double x_um = grid.origin_um.x() + i * grid.dx_um;
    if (x_um < start_um || x_um > end_um) continue;
    smallest_um =
        std::min(smallest_um, 2.0 * geometry::effective_radius_um(lattice.solid_mask, grid, i));
  }
  return smallest_um;
}

std::pair<double, double> narrow_section_um(const geometry::WallShape& shape,
                                            const CapillaryLattice& lattice,
                                            std::string_view source) {
  if (const auto* capillary = dynamic_cast<const geometry::CapillaryWall*>(&shape)) {
    return {capillary->constriction_start_um(), capillary->constriction_end_um()};
  }
  const auto& grid = lattice.grid_um;
  const auto area = [&](int i) {
    return geometry::slice_fluid_area_um2(lattice.solid_mask, grid, i);
  };
  const double threshold_um2 = kNarrowAreaFraction * std::min(area(1), area(grid.nx - 2));
  int first = -1;
  int last = -1;
  for (int i = 1; i < grid.nx - 1; ++i) {
    if (area(i) < threshold_um2) {
      if (first < 0) first = i;
      last = i;
    }
  }
  if (first < 0) {
    throw InputError(std::string(source), "the wall has no narrow section (no lumen slice below " +
                                              std::to_string(kNarrowAreaFraction) +
                                              " of the end slices' area)");
  }
  // Each slice stands for the dx-thick layer around its node.
  const double half_dx = 0.5 * grid.dx_um;
  return {grid.node_position_um(first, 0, 0).x() - half_dx,
          grid.node_position_um(last, 0, 0).x() + half_dx};
}

}  // namespace rbcsim::cases
