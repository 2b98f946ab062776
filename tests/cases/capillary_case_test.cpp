// The capillary experiment end to end at low resolution (dx = 1 um, the 162-vertex discocyte,
// 33 x 13 x 13 nodes): the settings come through the config bridge as a user's would, the cell
// is released at rest and carried through the paper's validation capillary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cases/capillary_case.hpp"
#include "common/errors.hpp"
#include "config/config.hpp"
#include "setup/capillary_from_config.hpp"
#include "setup/cell_from_config.hpp"

namespace rbcsim::cases {
namespace {

// The 162-vertex cell on dx = 1 um is too soft for the paper's flow: the link spring scales as
// 1 / L0 (Eq. 6), so at four times the paper's edge length its shear modulus is a quarter of the
// paper cell's and the run would be at Ca ~ 4. The test multiplies every k by 16 (G_s 30 uN/m)
// and doubles the velocity: Ca ~ 0.5, and a throat of 9 um, so the cell passes in ~5000 steps.
std::vector<std::string> coarse_settings() {
  return {"mesh.subdivisions=2",
          "mesh.method=parametric",  // the Evans-Fung cell these figures are for
          "lattice.spacing_um=1",
          "membrane.k_link_kBT=112",
          "membrane.k_area_kBT=80",
          "membrane.k_bend_kBT=800",
          "membrane.k_volume_kBT=320",
          "membrane.k_area_difference_kBT=4800",
          "membrane.k_total_curvature_kBT=1600",
          "membrane.vertex_force_cap_pN=2000",
          "capillary.throat_diameter_um=9",
          "capillary.inlet_velocity_m_per_s=0.014",
          "capillary.pass_margin_um=2",
          "capillary.sample_interval_s=2e-5",
          "capillary.fluid_tolerance=1e-5"};
}

CapillaryRun coarse_run(std::vector<std::string> assignments) {
  const auto config = config::resolve_config({.assignments = std::move(assignments)});
  const auto wall = setup::capillary_wall_from(config);
  const auto settings = setup::capillary_settings_from(config, wall);
  const auto cell = setup::cell_mesh_from(config);
  return run_capillary(cell.mesh, setup::capillary_physics_from(config, wall, cell.mesh, {}),
                       settings);
}

TEST(CapillaryCase, CellAxisTurnsTheMeshZAxis) {
  const mesh::TriangleMesh point{{Vec3(0.0, 0.0, 1.0)}, {}};
  EXPECT_LT((oriented_cell(point, "z").positions_um[0] - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((oriented_cell(point, "x").positions_um[0] - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((oriented_cell(point, "y").positions_um[0] - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((oriented_cell(point, "-z").positions_um[0] - Vec3(0, 0, -1)).norm(), 1e-15);
  EXPECT_LT((oriented_cell(point, "-x").positions_um[0] - Vec3(-1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((oriented_cell(point, "-y").positions_um[0] - Vec3(0, -1, 0)).norm(), 1e-15);
  EXPECT_THROW(oriented_cell(point, "w"), InputError);
}

// The paper's Fig. 13: DI starts at its inlet value (1, the disc in the x-y plane), rises as the
// throat squeezes the cell in y and falls back once it has left the narrow section.
TEST(CapillaryCase, CellIsCarriedThroughTheThroatAndItsDeformationIndexPeaksThere) {
  const auto run = coarse_run(coarse_settings());
  ASSERT_TRUE(run.ok()) << run.failure;
  EXPECT_TRUE(run.passed);
  EXPECT_NEAR(run.initial_deformation_index, 1.0, 0.01);
  EXPECT_GT(run.peak_deformation_index, run.initial_deformation_index + 0.1);
  EXPECT_GT(run.peak_centroid_x_um, run.narrow_start_um);
  EXPECT_LT(run.peak_centroid_x_um, run.narrow_end_um);
  EXPECT_LT(run.final_deformation_index, run.peak_deformation_index - 0.1);
  // On the axis the cell moves faster than the mean inflow, and never faster than the fastest
  // fluid: the Poiseuille peak in the throat, twice the mean there, U (D_in / D_throat)^2.
  ASSERT_TRUE(run.transit_time_s);
  const double length_m = (run.narrow_end_um - run.narrow_start_um) * 1e-6;
  const double throat_mean_m_per_s = 0.014 * (10.2 / 9.0) * (10.2 / 9.0);
  EXPECT_LT(*run.transit_time_s, length_m / 0.014);
  EXPECT_GT(*run.transit_time_s, length_m / (2.0 * throat_mean_m_per_s));
  // Downstream all the way.
  ASSERT_GE(run.samples.size(), 3u);
  for (std::size_t i = 1; i < run.samples.size(); ++i) {
    EXPECT_GT(run.samples[i].centroid_um.x(), run.samples[i - 1].centroid_um.x()) << i;
  }
  // Velocity inlet: the Reynolds number is the configured velocity's.
  EXPECT_NEAR(run.numbers.reynolds_number, 0.014 * 10.2e-6 / 1.1e-6, 1e-12);
}

// Why the paper's throat fails (docs/validation.md, capillary): in the 6.75 um throat the local
// area term (Eq. 8) at Table 2's weight (here x16, like every k) resists area change only within a
// sliver of its singular limit |d| = tau_a, narrower than what one explicit step moves a vertex
// there, so a triangle steps onto the limit. Neither the wall, the vertex cap nor the cell's
// mirror symmetry is involved: with the area term 16 times stiffer still, it acts before the
// sliver and the same cell in the same flow passes, the DI peaking in the narrow section.
std::vector<std::string> paper_throat_settings(const std::string& k_area_kBT) {
  auto settings = coarse_settings();
  settings.push_back("capillary.throat_diameter_um=6.75");
  settings.push_back("membrane.k_area_kBT=" + k_area_kBT);
  return settings;
}

TEST(CapillaryCase, AtTableTwosAreaWeightATriangleStepsOntoTheAreaLimitInThePaperThroat) {
  const auto run = coarse_run(paper_throat_settings("80"));
  EXPECT_FALSE(run.passed);
  EXPECT_NE(run.failure.find("membrane term 'area'"), std::string::npos) << run.failure;
  // The vertex cap acts at most on the last step, as the triangle shoots onto the limit.
  EXPECT_LE(run.force_capped_steps, 1u);
}

TEST(CapillaryCase, AStifferLocalAreaTermCarriesTheCellThroughThePaperThroat) {
  const auto run = coarse_run(paper_throat_settings("1280"));
  ASSERT_TRUE(run.ok()) << run.failure;
  EXPECT_TRUE(run.passed);
  EXPECT_GT(run.peak_deformation_index, run.initial_deformation_index + 0.3);
  EXPECT_GT(run.peak_centroid_x_um, run.narrow_start_um);
  EXPECT_LT(run.peak_centroid_x_um, run.narrow_end_um);
  EXPECT_LT(run.final_deformation_index, run.peak_deformation_index - 0.3);
}

// With no time limit given (capillary.max_time_s 0) a run may take as long as the mean inlet flow
// needs to cross the tube, so slow flows are not cut short: 31.2 um at 1e-4 m/s is 0.312 s. A
// limit that is given stays.
TEST(CapillaryCase, TheDefaultTimeLimitIsTheTimeTheMeanFlowTakesToCrossTheTube) {
  const auto settings_for = [](std::vector<std::string> assignments) {
    const auto config = config::resolve_config({.assignments = std::move(assignments)});
    return setup::capillary_settings_from(config, setup::capillary_wall_from(config));
  };
  constexpr double kValidationTubeLength_m = 31.2e-6;
  EXPECT_NEAR(settings_for({"capillary.inlet_velocity_m_per_s=1e-4"}).max_time_s,
              kValidationTubeLength_m / 1e-4, 1e-12);
  EXPECT_EQ(settings_for({"capillary.inlet_velocity_m_per_s=1e-4", "capillary.max_time_s=0.05"})
                .max_time_s,
            0.05);
}

// A discocyte 11 um across does not fit the 10.2 um inlet: bad input before any step, and
// before the fluid is settled (the test takes milliseconds).
TEST(CapillaryCase, ACellWiderThanTheInletIsBadInput) {
  auto settings = coarse_settings();
  settings.push_back("mesh.discocyte.radius_um=5.5");
  EXPECT_THROW(coarse_run(settings), InputError);
}

}  // namespace
}  // namespace rbcsim::cases

namespace rbcsim::cases {
namespace {

// The run of `assignments` as `rbcsim capillary` makes it: compressed as the config says, then
// converted back to physical units.
CapillaryRun compressed_run(std::vector<std::string> assignments) {
  const auto config = config::resolve_config({.assignments = std::move(assignments)});
  const auto wall = setup::capillary_wall_from(config);
  const auto compression = setup::capillary_compression_from(config, wall);
  const auto simulated = setup::compressed_capillary_config(config, wall, compression);
  const auto cell = setup::cell_mesh_from(simulated);
  auto run = run_capillary(cell.mesh, setup::capillary_physics_from(simulated, wall, cell.mesh, {}),
                           setup::capillary_settings_from(simulated, wall));
  setup::to_physical_units(run, compression);
  return run;
}

// DI of `run` at `time_s`, linear between its samples.
double deformation_index_at(const CapillaryRun& run, double time_s) {
  const auto& s = run.samples;
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (s[i].time_s >= time_s) {
      const double f = (time_s - s[i - 1].time_s) / (s[i].time_s - s[i - 1].time_s);
      return s[i - 1].deformation_index + f * (s[i].deformation_index - s[i - 1].deformation_index);
    }
  }
  return s.back().deformation_index;
}

// Low-Reynolds compression: at a quarter of the coarse case's velocity (Re 0.032, Ca ~0.12) the
// run compressed to Re 0.13 (factor 2, a quarter of the steps) gives, scaled back, the transit and
// the DI(t) of the uncompressed run within 2 % (the bound the method is held to; both stay in
// Stokes flow, where shapes depend on Ca alone).
TEST(CapillaryCase, CompressedRunScaledBackAgreesWithTheUncompressedRun) {
  auto settings = coarse_settings();
  settings.push_back("capillary.inlet_velocity_m_per_s=0.0035");
  settings.push_back("capillary.sample_interval_s=8e-5");
  auto plain = settings;
  plain.push_back("capillary.time_scale_compression=false");
  settings.push_back("capillary.max_reynolds_number=0.13");
  const auto slow = compressed_run(plain);
  const auto fast = compressed_run(settings);
  ASSERT_TRUE(slow.ok()) << slow.failure;
  ASSERT_TRUE(fast.ok()) << fast.failure;
  EXPECT_LT(fast.steps * 3, slow.steps);  // s^2 = 4 fewer steps, less the fluid's settling
  ASSERT_TRUE(slow.transit_time_s && fast.transit_time_s);
  EXPECT_NEAR(*fast.transit_time_s / *slow.transit_time_s, 1.0, 0.02);
  double worst = 0.0;
  for (const auto& sample : slow.samples) {
    if (sample.time_s > fast.samples.back().time_s) break;
    worst = std::max(
        worst,
        std::abs(deformation_index_at(fast, sample.time_s) / sample.deformation_index - 1.0));
  }
  EXPECT_LT(worst, 0.02) << "largest relative DI difference over the run";
}

// Single-precision populations (lattice.precision = single) against double on the coarse case:
// the transit time and DI(t) agree far inside the 2 % held to the time-scale compression (measured:
// the same transit to 7 digits, DI within 1.2e-7; float round-off of the populations, ~1e-5
// relative in the fluid's velocity, is all that differs).
TEST(CapillaryCase, SinglePrecisionPopulationsGiveTheDoubleRunsTransitAndDeformation) {
  auto single = coarse_settings();
  single.push_back("lattice.precision=single");
  const auto in_double = coarse_run(coarse_settings());
  const auto in_single = coarse_run(single);
  ASSERT_TRUE(in_double.ok()) << in_double.failure;
  ASSERT_TRUE(in_single.ok()) << in_single.failure;
  ASSERT_TRUE(in_double.transit_time_s && in_single.transit_time_s);
  EXPECT_NEAR(*in_single.transit_time_s / *in_double.transit_time_s, 1.0, 1e-4);
  double worst = 0.0;
  for (const auto& sample : in_double.samples) {
    if (sample.time_s > in_single.samples.back().time_s) break;
    worst = std::max(worst, std::abs(deformation_index_at(in_single, sample.time_s) /
                                         sample.deformation_index -
                                     1.0));
  }
  std::printf("single vs double: transit %.6e / %.6e s, largest DI difference %.3e\n",
              *in_single.transit_time_s, *in_double.transit_time_s, worst);
  EXPECT_LT(worst, 1e-5) << "largest relative DI difference over the run";
}

}  // namespace
}  // namespace rbcsim::cases
