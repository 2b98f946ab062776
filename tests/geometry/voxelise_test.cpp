#include "geometry/voxelise.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "common/errors.hpp"
#include "geometry/capillary_wall.hpp"
#include "geometry/channel_wall.hpp"
#include "geometry/tube_wall.hpp"
#include "geometry/wall_measures.hpp"

namespace {

using namespace rbcsim::geometry;
using rbcsim::Vec3;

struct TubeCase {
  double radius_over_dx;
  double offset_y_over_dx;  // shift of the lattice against the tube axis
  double offset_z_over_dx;
};

void PrintTo(const TubeCase& c, std::ostream* out) {
  *out << "R/dx " << c.radius_over_dx << ", offset (" << c.offset_y_over_dx << ", "
       << c.offset_z_over_dx << ") dx";
}

class VoxelisedTube : public ::testing::TestWithParam<TubeCase> {};

// Gauss circle bound: the cube of every fluid node lies inside the disc of radius R + dx/sqrt(2),
// and the cubes of the fluid nodes cover the disc of radius R - dx/sqrt(2), so per x-slice
// |N dx^2 - pi R^2| <= pi ((R + dx/sqrt(2))^2 - R^2) = pi (sqrt(2) R dx + dx^2 / 2).
TEST_P(VoxelisedTube, FluidNodeCountWithinTheStaircaseBound) {
  const auto [radius_over_dx, offset_y, offset_z] = GetParam();
  const double dx_um = 0.5;
  const double radius_um = radius_over_dx * dx_um;
  const TubeWall tube({2.0 * radius_um, 6.0});
  LatticeGrid grid = lattice_around(tube, dx_um);
  grid.origin_um += dx_um * Vec3(0.0, offset_y, offset_z);
  const auto mask = voxelise(tube, grid);

  const double length_um = grid.nx * dx_um;
  const double expected_nodes =
      std::numbers::pi * radius_um * radius_um * length_um / (dx_um * dx_um * dx_um);
  const double bound_nodes = grid.nx * std::numbers::pi * (std::sqrt(2.0) * radius_over_dx + 0.5);
  EXPECT_NEAR(static_cast<double>(fluid_node_count(mask)), expected_nodes, bound_nodes);
  // Per slice, as a radius: |R_eff - R| <= dx / sqrt(2) follows from the same two discs.
  for (int i = 0; i < grid.nx; ++i) {
    EXPECT_NEAR(effective_radius_um(mask, grid, i), radius_um, dx_um / std::sqrt(2.0));
  }
}

INSTANTIATE_TEST_SUITE_P(RadiiAndOffsets, VoxelisedTube,
                         ::testing::Values(TubeCase{4.3, 0.0, 0.0}, TubeCase{7.5, 0.37, 0.11},
                                           TubeCase{10.0, 0.5, 0.5}, TubeCase{12.7, 0.21, 0.73},
                                           TubeCase{20.0, 0.0, 0.0}));

TEST(Voxelise, NodeCentredIndexOrder) {
  // An anisotropic grid: node (i, j, k) at origin + (i, j, k) dx, stored at i + nx (j + ny k).
  const TubeWall tube({6.0, 10.0});
  const LatticeGrid grid{Vec3(0.25, -3.7, -2.9), 0.5, 7, 15, 12};
  const auto mask = voxelise(tube, grid);
  ASSERT_EQ(mask.size(), 7u * 15u * 12u);
  std::size_t index = 0;
  for (int k = 0; k < 12; ++k) {
    for (int j = 0; j < 15; ++j) {
      for (int i = 0; i < 7; ++i, ++index) {
        const double y = -3.7 + 0.5 * j;
        const double z = -2.9 + 0.5 * k;
        EXPECT_EQ(mask[index], y * y + z * z < 9.0 ? kFluid : kSolid) << i << " " << j << " " << k;
      }
    }
  }
}

TEST(Voxelise, ChannelPlatesLieHalfwayBetweenNodes) {
  const ChannelWall channel({10.0, 8.0, 6.0});
  for (int wall_layers : {1, 3}) {
    const auto grid = lattice_around(channel, 0.5, wall_layers);
    EXPECT_EQ(grid.nx, 16);  // open: length / dx
    EXPECT_EQ(grid.nz, 12);  // open: width / dx
    EXPECT_EQ(grid.ny, 20 + 2 * wall_layers);
    const auto mask = voxelise(channel, grid);
    for (int k = 0; k < grid.nz; ++k) {
      EXPECT_DOUBLE_EQ(effective_gap_um(mask, grid, 3, k), 10.0);
    }
    // The last fluid node and the first solid one sit dx/2 either side of the plate y = 5.
    const int top_fluid = grid.ny - wall_layers - 1;
    EXPECT_DOUBLE_EQ(grid.node_position_um(0, top_fluid, 0).y(), 4.75);
    EXPECT_EQ(mask[grid.index(0, top_fluid, 0)], kFluid);
    EXPECT_EQ(mask[grid.index(0, top_fluid + 1, 0)], kSolid);
    EXPECT_DOUBLE_EQ(grid.node_position_um(0, 0, 0).x(), 0.25);
  }
}

TEST(Voxelise, LatticeAroundTubeHasAWallLayerAndCoversTheLength) {
  const TubeWall tube({10.2, 31.2});
  const auto grid = lattice_around(tube, 0.5);
  EXPECT_EQ(grid.nx, 62);  // round(31.2 / 0.5)
  EXPECT_EQ(grid.ny, 23);  // ceil(10.2 / 0.5) + 2
  EXPECT_EQ(grid.nz, 23);
  EXPECT_NEAR(grid.node_position_um(0, 11, 11).y(), 0.0, 1e-12);  // axis centred
  const auto mask = voxelise(tube, grid);
  for (int i = 0; i < grid.nx; ++i) {
    for (int t = 0; t < grid.ny; ++t) {
      EXPECT_EQ(mask[grid.index(i, 0, t)], kSolid);
      EXPECT_EQ(mask[grid.index(i, grid.ny - 1, t)], kSolid);
      EXPECT_EQ(mask[grid.index(i, t, 0)], kSolid);
      EXPECT_EQ(mask[grid.index(i, t, grid.nz - 1)], kSolid);
    }
  }
  // The volume fraction is the fluid count over all nodes.
  EXPECT_DOUBLE_EQ(fluid_volume_fraction(mask),
                   static_cast<double>(fluid_node_count(mask)) / (62.0 * 23.0 * 23.0));
}

TEST(Voxelise, RejectsBadGrids) {
  const TubeWall tube({4.0, 4.0});
  EXPECT_THROW(lattice_around(tube, 0.0), rbcsim::InputError);
  EXPECT_THROW(lattice_around(tube, -0.5), rbcsim::InputError);
  EXPECT_THROW(lattice_around(tube, 0.5, 0), rbcsim::InputError);
  EXPECT_THROW(lattice_around(tube, 1e-9), rbcsim::InputError);  // 4e9 nodes per axis
  EXPECT_THROW(voxelise(tube, LatticeGrid{Vec3::Zero(), 0.5, 0, 4, 4}), rbcsim::InputError);
  EXPECT_THROW(voxelise(tube, LatticeGrid{Vec3::Zero(), std::nan(""), 4, 4, 4}),
               rbcsim::InputError);
}

TEST(Voxelise, CapillaryThroatNarrowerThanInletOnTheLattice) {
  const CapillaryWall capillary(paper_validation_capillary());
  const auto grid = lattice_around(capillary, 0.25);
  const auto mask = voxelise(capillary, grid);
  const int throat_i = static_cast<int>(std::lround((15.6 - grid.origin_um.x()) / 0.25));
  for (int i : {0, throat_i, grid.nx - 1}) {
    const double x_um = grid.node_position_um(i, 0, 0).x();
    EXPECT_NEAR(effective_radius_um(mask, grid, i), *capillary.radius_at_um(x_um),
                0.25 / std::sqrt(2.0))
        << "x = " << x_um;
  }
}

TEST(Voxelise, CapillaryOnHundredByThirtyByThirtyIsFast) {
  const CapillaryWall capillary(paper_morphology_capillary());
  const LatticeGrid grid{Vec3(0.21, -7.25, -7.25), 0.42, 100, 30, 30};
  const auto start = std::chrono::steady_clock::now();
  const auto mask = voxelise(capillary, grid);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_LT(elapsed.count(), 0.1);  // the brief's budget; it takes about a millisecond
  EXPECT_GT(fluid_node_count(mask), 0u);
}

class InletProfile : public ::testing::TestWithParam<TubeCase> {};

TEST_P(InletProfile, PoiseuilleAboutTheEffectiveRadiusWithMeanOne) {
  const auto [radius_over_dx, offset_y, offset_z] = GetParam();
  const double dx_um = 0.5;
  const TubeWall tube({2.0 * radius_over_dx * dx_um, 2.0});
  LatticeGrid grid = lattice_around(tube, dx_um);
  grid.origin_um += dx_um * Vec3(0.0, offset_y, offset_z);
  const auto mask = voxelise(tube, grid);
  const auto profile = poiseuille_inlet_profile(mask, grid, 0);
  ASSERT_EQ(profile.size(), static_cast<std::size_t>(grid.ny * grid.nz));

  // The profile is centred on the fluid nodes' centroid, not on the tube's axis.
  Vec3 centroid = Vec3::Zero();
  double fluid_nodes = 0.0;
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      if (mask[grid.index(0, j, k)] == kFluid) {
        centroid += grid.node_position_um(0, j, k);
        fluid_nodes += 1.0;
      }
    }
  }
  centroid /= fluid_nodes;
  const double radius_um = effective_radius_um(mask, grid, 0);
  double sum = 0.0;
  double scale = 0.0;  // profile / analytic, the same at every node inside R_eff
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      const double value = profile[j + grid.ny * k];
      const Vec3 node = grid.node_position_um(0, j, k);
      const double analytic = poiseuille_velocity_ratio(
          std::hypot(node.y() - centroid.y(), node.z() - centroid.z()), radius_um);
      if (mask[grid.index(0, j, k)] == kSolid || analytic == 0.0) {
        EXPECT_EQ(value, 0.0);
        continue;
      }
      sum += value;
      if (scale == 0.0) scale = value / analytic;
      EXPECT_NEAR(value / analytic, scale, 1e-12);
    }
  }
  EXPECT_NEAR(sum / fluid_nodes, 1.0, 1e-12);
  // Without the clamp at R_eff, 1 / scale = 2 - 2 <r^2> / R_eff^2 exactly: the error of the
  // staircase section's polar moment against the disc of the same area, second order in dx/R
  // (each cell's centre misses r^2 by dx^2/6 and the boundary cells' errors largely cancel).
  // Measured below 0.2 (dx/R)^2 over R/dx = 3..60 and lattice offsets; the bound allows 1.
  EXPECT_NEAR(scale, 1.0, 1.0 / (radius_over_dx * radius_over_dx));
}

INSTANTIATE_TEST_SUITE_P(RadiiAndOffsets, InletProfile,
                         ::testing::Values(TubeCase{5.0, 0.0, 0.0}, TubeCase{7.5, 0.37, 0.11},
                                           TubeCase{10.0, 0.5, 0.5}, TubeCase{20.0, 0.21, 0.73}));

TEST(WallMeasures, PoiseuilleFormula) {
  EXPECT_DOUBLE_EQ(poiseuille_velocity_ratio(0.0, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(poiseuille_velocity_ratio(1.0, 2.0), 1.5);
  EXPECT_DOUBLE_EQ(poiseuille_velocity_ratio(2.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(poiseuille_velocity_ratio(3.0, 2.0), 0.0);
  // Mean over the disc: int_0^R 2 (1 - r^2/R^2) 2 pi r dr / (pi R^2) = 1.
  double mean = 0.0;
  const int steps = 100000;
  for (int s = 0; s < steps; ++s) {
    const double r = (s + 0.5) / steps;
    mean += poiseuille_velocity_ratio(r, 1.0) * 2.0 * r / steps;
  }
  EXPECT_NEAR(mean, 1.0, 1e-9);
}

TEST(WallMeasures, RejectsMismatchedMasksAndSolidInlets) {
  const TubeWall tube({4.0, 4.0});
  const auto grid = lattice_around(tube, 0.5);
  const auto mask = voxelise(tube, grid);
  EXPECT_THROW(effective_radius_um(SolidMask(3, kFluid), grid, 0), std::invalid_argument);
  EXPECT_THROW(effective_radius_um(mask, grid, grid.nx), std::out_of_range);
  EXPECT_THROW(effective_gap_um(mask, grid, 0, -1), std::out_of_range);
  const SolidMask all_solid(grid.node_count(), kSolid);
  EXPECT_THROW(poiseuille_inlet_profile(all_solid, grid, 0), rbcsim::InputError);
  EXPECT_DOUBLE_EQ(fluid_volume_fraction(all_solid), 0.0);
}

}  // namespace
