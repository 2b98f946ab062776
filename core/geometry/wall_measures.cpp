#include "geometry/wall_measures.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"

namespace rbcsim::geometry {
namespace {

void require_matching(const SolidMask& solid_mask, const LatticeGrid& grid) {
  if (solid_mask.size() != grid.node_count()) {
    throw std::invalid_argument("solid mask of " + std::to_string(solid_mask.size()) +
                                " nodes for a grid of " + std::to_string(grid.node_count()));
  }
}

void require_index(int index, int count, const char* axis) {
  if (index < 0 || index >= count) {
    throw std::out_of_range(std::string(axis) + " index " + std::to_string(index) + " outside 0.." +
                            std::to_string(count - 1));
  }
}

void require_slice(const SolidMask& solid_mask, const LatticeGrid& grid, int i) {
  require_matching(solid_mask, grid);
  require_index(i, grid.nx, "x");
}

// Calls visit(j, k, node position) for every fluid node of the x-slice i.
template <class Visit>
void for_each_fluid_node_of_slice(const SolidMask& solid_mask, const LatticeGrid& grid, int i,
                                  Visit&& visit) {
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      if (solid_mask[grid.index(i, j, k)] == kFluid) visit(j, k, grid.node_position_um(i, j, k));
    }
  }
}

std::size_t slice_fluid_nodes(const SolidMask& solid_mask, const LatticeGrid& grid, int i) {
  std::size_t count = 0;
  for_each_fluid_node_of_slice(solid_mask, grid, i, [&count](int, int, const Vec3&) { ++count; });
  return count;
}

}  // namespace

std::size_t fluid_node_count(const SolidMask& solid_mask) {
  return static_cast<std::size_t>(std::count(solid_mask.begin(), solid_mask.end(), kFluid));
}

double fluid_volume_fraction(const SolidMask& solid_mask) {
  if (solid_mask.empty()) throw std::invalid_argument("fluid_volume_fraction of an empty mask");
  return static_cast<double>(fluid_node_count(solid_mask)) / static_cast<double>(solid_mask.size());
}

double slice_fluid_area_um2(const SolidMask& solid_mask, const LatticeGrid& grid, int i) {
  require_slice(solid_mask, grid, i);
  return static_cast<double>(slice_fluid_nodes(solid_mask, grid, i)) * grid.dx_um * grid.dx_um;
}

double effective_radius_um(const SolidMask& solid_mask, const LatticeGrid& grid, int i) {
  return std::sqrt(slice_fluid_area_um2(solid_mask, grid, i) / std::numbers::pi);
}

double effective_gap_um(const SolidMask& solid_mask, const LatticeGrid& grid, int i, int k) {
  require_slice(solid_mask, grid, i);
  require_index(k, grid.nz, "z");
  std::size_t count = 0;
  for (int j = 0; j < grid.ny; ++j) count += solid_mask[grid.index(i, j, k)] == kFluid;
  return static_cast<double>(count) * grid.dx_um;
}

double poiseuille_velocity_ratio(double r_um, double radius_um) {
  const double relative = r_um / radius_um;
  return relative < 1.0 ? 2.0 * (1.0 - relative * relative) : 0.0;
}

std::vector<double> poiseuille_inlet_profile(const SolidMask& solid_mask, const LatticeGrid& grid,
                                             int i) {
  require_slice(solid_mask, grid, i);
  const auto fluid_nodes = slice_fluid_nodes(solid_mask, grid, i);
  if (fluid_nodes == 0) {
    throw InputError("inlet profile",
                     "the x-slice " + std::to_string(i) + " of the lattice has no fluid node");
  }
  Eigen::Vector2d axis_um = Eigen::Vector2d::Zero();
  for_each_fluid_node_of_slice(solid_mask, grid, i, [&axis_um](int, int, const Vec3& node_um) {
    axis_um += node_um.tail<2>();
  });
  axis_um /= static_cast<double>(fluid_nodes);
  const double radius_um = effective_radius_um(solid_mask, grid, i);

  std::vector<double> profile(static_cast<std::size_t>(grid.ny) * grid.nz, 0.0);
  double sum = 0.0;
  for_each_fluid_node_of_slice(solid_mask, grid, i, [&](int j, int k, const Vec3& node_um) {
    const double ratio = poiseuille_velocity_ratio((node_um.tail<2>() - axis_um).norm(), radius_um);
    profile[static_cast<std::size_t>(j) + static_cast<std::size_t>(grid.ny) * k] = ratio;
    sum += ratio;
  });
  if (sum == 0.0) {
    throw InputError("inlet profile", "the x-slice " + std::to_string(i) +
                                          " is not a circular section: no fluid node lies within "
                                          "its effective radius of its centroid");
  }
  const double mean = sum / static_cast<double>(fluid_nodes);
  for (auto& value : profile) value /= mean;
  return profile;
}

}  // namespace rbcsim::geometry
