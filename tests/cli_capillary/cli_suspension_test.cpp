// `rbcsim capillary --geometry tube --hematocrit H`, end to end on a coarse set-up (two
// 162-vertex cells on dx = 1 um): the run directory (result.json against the schema, the two time
// series, one ParaView series for all cells with their ids), cells that touch in the flow without
// piercing each other (642-vertex cells), a resumed run that rewrites a straight one's results,
// and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "io/csv_table.hpp"
#include "support/run_rbcsim.hpp"
#include "support/run_result.hpp"
#include "support/scratch_directory.hpp"

namespace {

namespace fs = std::filesystem;
using rbcsim::testing::printed_run_result;
using rbcsim::testing::read_lines;
using rbcsim::testing::read_text;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

// The contact's range must bridge the 162-vertex cells' edges (up to 1.66 um).
constexpr const char* kCoarseTube =
    "capillary --geometry tube --diameter-um 10 --length-um 12 --set mesh.subdivisions=2 "
    "--set mesh.method=parametric --set lattice.spacing_um=1 --set "
    "suspension.contact_range_um=1.75 "
    "--set suspension.duration_s=2e-4 --set suspension.sample_interval_s=2e-5 "
    "--set output.membrane_interval_s=1e-4 --set output.fluid_interval_s=1e-4 ";

TEST(CliSuspension, WritesTheRunDirectoryOfAMixedSuspension) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string(kCoarseTube) +
                                     "--hematocrit 0.2 --mix discocyte=0.5,stomatocyte-II=0.5 "
                                     "--threads 2 --json --output '" +
                                     run_dir.string() + "'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // 1.75 um of contact range on dx 1 um: inside the phi2 kernel's 2 um.
  EXPECT_NE(result.err.find("shorter than the phi2 kernel's width (2 x 1 um)"), std::string::npos)
      << result.err;
  const auto printed = printed_run_result(result, run_dir, "capillary");
  const auto& suspension = printed["suspension"];
  EXPECT_EQ(suspension["cells"], 2);
  EXPECT_EQ(suspension["cells_per_morphology"]["discocyte"], 1);
  EXPECT_EQ(suspension["cells_per_morphology"]["stomatocyte-II"], 1);
  EXPECT_EQ(suspension["time_scale"]["compressed"], true);
  EXPECT_NEAR(suspension["time_s"].get<double>(), 2e-4, 1e-6);
  // Cells in the flow hold it back: the plasma flows faster under the same gradient.
  EXPECT_GT(suspension["relative_apparent_viscosity"].get<double>(), 1.0);
  EXPECT_EQ(suspension["tube_hematocrit"], suspension["packed_hematocrit"]);
  EXPECT_EQ(suspension["close_contact_steps"], 0);
  EXPECT_EQ(suspension["samples_with_pierced_cells"], 0);
  // The drive: plasma alone at the mean velocity asked for, Q = pi R^2 U (2 mm/s in the 10 um
  // tube), reported in physical units after the time-scale compression. The lattice resolves
  // the diameter with 10 nodes; its interpolated walls are within 1 % of Poiseuille there
  // (tests/lattice/curved_wall_test.cpp: 0.2 % at 20 nodes, second order).
  EXPECT_NEAR(
      suspension["plasma_flow_rate_um3_per_s"].get<double>() / (3.14159265358979 * 25.0 * 2000.0),
      1.0, 0.02);

  // The hematocrit profile (10 rings of 0.5 um) integrates to the cells' volume over the lumen's:
  // the tube hematocrit, to the cells' change of volume in the flow (the volume term holds it
  // within 1 %) and the profile's lines (0.1 um squares, 1 % on these cells).
  const auto& profile = suspension["hematocrit_profile"];
  ASSERT_EQ(profile["volume_fraction"].size(), 10u);
  EXPECT_EQ(profile["ring_outer_radius_um"].back(), 5.0);
  double integrated = 0.0;
  for (std::size_t ring = 0; ring < 10; ++ring) {
    const double inner = profile["ring_inner_radius_um"][ring].get<double>() / 5.0;
    const double outer = profile["ring_outer_radius_um"][ring].get<double>() / 5.0;
    integrated += profile["volume_fraction"][ring].get<double>() * (outer * outer - inner * inner);
  }
  EXPECT_NEAR(integrated, suspension["tube_hematocrit"].get<double>(),
              0.02 * suspension["tube_hematocrit"].get<double>());

  const auto flow = rbcsim::io::read_csv_file(run_dir / "suspension_timeseries.csv");
  const auto time_s = flow.numbers("time_s");
  ASSERT_GE(time_s.size(), 5u);
  EXPECT_EQ(time_s.front(), 0.0);
  const auto cells = rbcsim::io::read_csv_file(run_dir / "cells_timeseries.csv");
  EXPECT_EQ(cells.numbers("cell_id").size(), 2 * time_s.size());
  // How far the flow carried the cells: each cell's centroid from its first row to its last
  // (rows in time order), averaged; downstream, and in tube diameters too.
  const auto ids = cells.numbers("cell_id");
  const auto centroid_x = cells.numbers("centroid_x_um");
  std::map<double, std::pair<double, double>> ends_um;  // cell -> (first x, last x)
  for (std::size_t row = 0; row < ids.size(); ++row) {
    if (!ends_um.contains(ids[row])) ends_um[ids[row]].first = centroid_x[row];
    ends_um[ids[row]].second = centroid_x[row];
  }
  double travel_um = 0.0;
  for (const auto& [id, ends] : ends_um) travel_um += (ends.second - ends.first) / 2.0;
  EXPECT_GT(travel_um, 0.0);
  EXPECT_NEAR(suspension["cell_travel_um"].get<double>(), travel_um, 1e-9 * travel_um);
  EXPECT_NEAR(suspension["cell_travel_tube_diameters"].get<double>(), travel_um / 10.0,
              1e-9 * travel_um);
  const auto rings = rbcsim::io::read_csv_file(run_dir / "hematocrit_profile.csv");
  EXPECT_EQ(rings.numbers("volume_fraction").size(), 10 * time_s.size());
  const auto pvd = read_text(run_dir / "cells.pvd");
  EXPECT_NE(pvd.find("<DataSet"), std::string::npos);
  EXPECT_FALSE(fs::exists(run_dir / "cell0.pvd"));
  bool found = false;
  for (const auto& entry : fs::directory_iterator(run_dir / "vtk")) {
    if (entry.path().filename().string().rfind("cells_", 0) != 0) continue;
    const auto vtp = read_text(entry.path());
    EXPECT_NE(vtp.find("Name=\"cell_id\""), std::string::npos);
    EXPECT_NE(vtp.find("Name=\"cell_kind\""), std::string::npos);
    found = true;
  }
  EXPECT_TRUE(found);

  // `rbcsim report` gives it the suspension section (its time series, the comparison with
  // Pries et al. at its diameter and measured H_D, its centres across the tube), not a transit.
  const auto report_dir = scratch.path() / "report";
  const auto report =
      run_rbcsim("report '" + run_dir.string() + "' --json --output '" + report_dir.string() + "'",
                 scratch.path());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const auto html = read_text(report_dir / "report.html");
  EXPECT_NE(html.find("Suspensions in a straight tube"), std::string::npos);
  EXPECT_EQ(html.find("Capillary transit"), std::string::npos);
  const auto summary = nlohmann::json::parse(report.out);
  ASSERT_EQ(summary["suspension"]["runs"].size(), 1u);
  const auto& density = summary["suspension"]["runs"][0]["centre_density"];
  EXPECT_EQ(density["discocyte"].size(), 10u);
  EXPECT_EQ(density["stomatocyte-II"].size(), 10u);
  EXPECT_GE(summary["suspension"]["comparisons"].size(), 2u);  // viscosity and H_T / H_D
  // 0.2 ms of flow has not developed: the numbers are there, the verdict is not.
  for (const auto& comparison : summary["suspension"]["comparisons"]) {
    EXPECT_TRUE(comparison["verdict"].get<std::string>().starts_with("not developed"))
        << comparison["verdict"];
  }
}

// Four discocytes of 642 vertices in a 10 um tube: in the Poiseuille flow the cells nearer the
// axis overtake the others and come within the contact's range (sheared collisions); no surface
// may pass through another at any sample (the winding number of the other's surface). In this
// short run the plasma film alone also keeps them apart (with the contact off, nothing pierces):
// the test guards against a contact that drags surfaces into each other; that the measure finds
// piercings is tested in tests/cases/suspension_packing_test.cpp.
TEST(CliSuspension, CellsOvertakingEachOtherInTubeFlowNeverInterpenetrate) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(
      "capillary --geometry tube --diameter-um 10 --length-um 24 --hematocrit 0.2 "
      "--set mesh.subdivisions=3 --set mesh.method=parametric --set suspension.duration_s=2e-3 "
      "--set suspension.sample_interval_s=5e-5 --set output.membrane_interval_s=0 "
      "--set output.fluid_interval_s=0 --threads 2 --json --output '" +
          run_dir.string() + "'",
      scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err.find("kernel's width"), std::string::npos) << result.err;  // 1 um on dx 0.5
  const auto suspension = printed_run_result(result, run_dir, "capillary")["suspension"];
  ASSERT_EQ(suspension["cells"], 4);
  EXPECT_EQ(suspension["samples_with_pierced_cells"], 0);
  const auto flow = rbcsim::io::read_csv_file(run_dir / "suspension_timeseries.csv");
  const auto contact_pairs = flow.numbers("contact_pairs");
  const auto pierced = flow.numbers("pierced_cells");
  EXPECT_GT(*std::max_element(contact_pairs.begin(), contact_pairs.end()), 0.0);
  EXPECT_EQ(*std::max_element(pierced.begin(), pierced.end()), 0.0);
}

// Cells packed at 0.8 of their size grow to it in the flow (suspension.packing_scale): the tube
// hematocrit starts at 0.8^3 of the packed one, reaches it once they have grown, and the averages
// (after the growth) are the full-size cells'. On dx 0.5 um with the wall's push over 1 um, as
// the validation's tubes (on dx 1 um the paper's membrane fails in this tube within 1 ms, grown
// or not).
TEST(CliSuspension, CellsPackedSmallerGrowToTheirSizeInTheFlow) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(
      "capillary --geometry tube --diameter-um 10 --length-um 12 --set mesh.subdivisions=2 "
      "--set mesh.method=parametric --set suspension.contact_range_um=1.75 "
      "--set suspension.wall_repulsion_range_um=1 --set suspension.duration_s=1.2e-3 "
      "--set suspension.sample_interval_s=1e-4 --set output.membrane_interval_s=0 "
      "--set output.fluid_interval_s=0 --hematocrit 0.2 --set suspension.packing_scale=0.8 "
      "--set suspension.growth_time_s=5e-4 --threads 2 --json --output '" +
          run_dir.string() + "'",
      scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto suspension = printed_run_result(result, run_dir, "capillary")["suspension"];
  EXPECT_EQ(suspension["packing_scale"], 0.8);
  EXPECT_EQ(suspension["growth_time_s"], 5e-4);  // physical, as asked (the run's is compressed)
  // The mean of samples equal to the packed hematocrit, to its round-off.
  EXPECT_DOUBLE_EQ(suspension["tube_hematocrit"].get<double>(),
                   suspension["packed_hematocrit"].get<double>());
  EXPECT_EQ(suspension["samples_with_pierced_cells"], 0);
  const auto flow = rbcsim::io::read_csv_file(run_dir / "suspension_timeseries.csv");
  const auto time_s = flow.numbers("time_s");
  const auto tube_hematocrit = flow.numbers("tube_hematocrit");
  const double packed = suspension["packed_hematocrit"].get<double>();
  ASSERT_GE(time_s.size(), 10u);
  EXPECT_NEAR(tube_hematocrit.front(), 0.512 * packed, 1e-12);
  for (std::size_t row = 1; row < time_s.size(); ++row) {
    EXPECT_GE(tube_hematocrit[row], tube_hematocrit[row - 1]) << "row " << row;
    if (time_s[row] >= 5e-4 + 1e-9) {
      EXPECT_EQ(tube_hematocrit[row], packed) << "row " << row;
    }
  }
}

// Two cells placed by hand (suspension.cells) instead of packed: the run takes them where they
// are put, names their morphologies, and measures its hematocrit from them.
TEST(CliSuspension, RunsCellsPlacedByHand) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(
      std::string(kCoarseTube) +
          "--set 'suspension.cells=[{\"morphology\": \"stomatocyte-II\", \"centre_um\": [2, "
          "0, 0], \"axis\": [1, 0, 0]}, {\"morphology\": \"discocyte\", \"centre_um\": [8, "
          "0.5, 0], \"axis\": [1, 0.2, 0]}]' --quiet --json --output '" +
          run_dir.string() + "'",
      scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto suspension = printed_run_result(result, run_dir, "capillary")["suspension"];
  EXPECT_EQ(suspension["cells"], 2);
  EXPECT_EQ(suspension["morphologies"], (nlohmann::json{"stomatocyte-II", "discocyte"}));
  EXPECT_EQ(suspension["packing_iterations"], 0);
  EXPECT_EQ(suspension["samples_with_pierced_cells"], 0);
  const auto cells = rbcsim::io::read_csv_file(run_dir / "cells_timeseries.csv");
  // The first sample (t = 0): the cells where they were put. The table's centroid is the mean
  // of the vertices: the symmetric discocyte's is its solid centroid; the cup-shaped
  // stomatocyte's lies off it along the cup's axis (here x) by a fraction of its thickness.
  const auto x = cells.numbers("centroid_x_um");
  const auto y = cells.numbers("centroid_y_um");
  const auto z = cells.numbers("centroid_z_um");
  EXPECT_NEAR(x[0], 2.0, 0.6);
  EXPECT_NEAR(y[0], 0.0, 1e-3);  // the generated meshes are symmetric to about 1e-5 um
  EXPECT_NEAR(z[0], 0.0, 1e-3);
  EXPECT_NEAR(x[1], 8.0, 1e-3);
  EXPECT_NEAR(y[1], 0.5, 1e-3);
  EXPECT_NEAR(z[1], 0.0, 1e-3);
  EXPECT_EQ(cells.numbers("morphology_index")[0], 0.0);
  EXPECT_EQ(cells.numbers("morphology_index")[1], 1.0);
}

// A cell of suspension.cells may bring its own mesh file, with its morphology's membrane: it is
// a kind of its own, named after the file, and its volume is the file's (the hematocrit of the
// placed cells is the sum of their true volumes over the lumen's).
TEST(CliSuspension, RunsACellOfAMeshFile) {
  const ScratchDirectory scratch;
  // rbcsim runs in the test's working directory: every file by its full path.
  const auto disc = (scratch.path() / "disc.stl").string();
  const auto small = (scratch.path() / "small.stl").string();
  const auto generated =
      run_rbcsim("mesh generate --method parametric --subdivisions 2 --json -o '" + disc + "'",
                 scratch.path());
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  const double disc_um3 =
      nlohmann::json::parse(generated.out)["report"]["size"]["volume_um3"].get<double>();
  // The file's cell: the same discocyte shrunk to 60 um^3, well below the discocyte's ~90.
  const double small_um3 = 60.0;
  ASSERT_EQ(
      run_rbcsim("mesh import '" + disc + "' --scale-to-volume 60 --center -o '" + small + "'",
                 scratch.path())
          .exit_code,
      0);
  const auto cell_list = [](const std::string& file) {
    return "--set 'suspension.cells=[{\"morphology\": \"discocyte\", \"mesh_file\": \"" + file +
           "\", \"centre_um\": [2, 0, 0], \"axis\": [1, 0, 0]}, {\"morphology\": \"discocyte\", "
           "\"centre_um\": [8, 0.5, 0], \"axis\": [1, 0.2, 0]}]' ";
  };
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string(kCoarseTube) + cell_list(small) +
                                     "--quiet --json --output '" + run_dir.string() + "'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto suspension = printed_run_result(result, run_dir, "capillary")["suspension"];
  EXPECT_EQ(suspension["morphologies"], (nlohmann::json{"discocyte (" + small + ")", "discocyte"}));
  const double lumen_um3 = std::numbers::pi * 5.0 * 5.0 * 12.0;
  // The STL's float32 coordinates move the volume by ~1e-7 of it.
  EXPECT_NEAR(suspension["packed_hematocrit"].get<double>() * lumen_um3, small_um3 + disc_um3,
              1e-5 * (small_um3 + disc_um3));

  const auto missing_dir = scratch.path() / "missing";
  const auto missing = run_rbcsim(std::string(kCoarseTube) + cell_list("/nonexistent/none.stl") +
                                      "--output '" + missing_dir.string() + "'",
                                  scratch.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("none.stl"), std::string::npos) << missing.err;
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  EXPECT_FALSE(fs::exists(missing_dir));
}

// --checkpoint-every leaves the run's last checkpoint in its directory; --resume of that directory
// runs the steps after it again and must rewrite the same "suspension" object of result.json, the
// same two time series (the samples before the checkpoint come from it) and snapshot collections.
TEST(CliSuspension, ResumeRewritesTheStraightRunsResults) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const std::string settings =
      std::string(kCoarseTube) + "--hematocrit 0.2 --mix discocyte=0.5,stomatocyte-II=0.5 --quiet ";
  const auto straight = run_rbcsim(
      settings + "--checkpoint-every 50 --output '" + run_dir.string() + "'", scratch.path());
  ASSERT_EQ(straight.exit_code, 0) << straight.err;
  ASSERT_TRUE(fs::exists(run_dir / "checkpoint.bin"));
  const auto straight_result = nlohmann::json::parse(read_text(run_dir / "result.json"));
  const auto straight_flow = read_lines(run_dir / "suspension_timeseries.csv");
  const auto straight_cells = read_lines(run_dir / "cells_timeseries.csv");
  const auto straight_profile = read_lines(run_dir / "hematocrit_profile.csv");
  const auto straight_membranes = read_lines(run_dir / "cells.pvd");
  const auto straight_fluid = read_lines(run_dir / "fluid.pvd");
  ASSERT_GT(straight_result["suspension"]["steps"].get<double>(), 50.0);
  for (const char* name : {"result.json", "suspension_timeseries.csv", "cells_timeseries.csv",
                           "hematocrit_profile.csv"}) {
    fs::remove(run_dir / name);
  }

  const auto resumed = run_rbcsim(settings + "--resume '" + run_dir.string() + "'", scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto resumed_result = nlohmann::json::parse(read_text(run_dir / "result.json"));
  EXPECT_EQ(resumed_result["suspension"], straight_result["suspension"]);
  EXPECT_EQ(read_lines(run_dir / "suspension_timeseries.csv"), straight_flow);
  EXPECT_EQ(read_lines(run_dir / "cells_timeseries.csv"), straight_cells);
  EXPECT_EQ(read_lines(run_dir / "hematocrit_profile.csv"), straight_profile);
  EXPECT_EQ(read_lines(run_dir / "cells.pvd"), straight_membranes);
  EXPECT_EQ(read_lines(run_dir / "fluid.pvd"), straight_fluid);
}

TEST(CliSuspension, BadInputExitsTwoWithOneLineAndNoRunDirectory) {
  const ScratchDirectory scratch;
  const auto out = (scratch.path() / "run").string();
  for (const auto& [arguments, named] : {
           std::pair<std::string, std::string>{
               "--hematocrit 0.2 --mix discocyte=0.5,stomatocyte-II=0.4", "suspension.mix"},
           {"--hematocrit 0.2 --mix discocyte=1,platelet=0", "suspension.mix"},
           {"--hematocrit 0.7 --set suspension.packing_max_iterations=100", "could not pack"},
           {"--hematocrit 0.2 --set suspension.contact_range_um=0.5",
            "suspension.contact_range_um"},
           {"--hematocrit 0.2 --orientations 3", "capillary.orientations"},
           {"--hematocrit 0.2 --set suspension.packing_scale=0.8 "
            "--set suspension.growth_time_s=1.5e-4",
            "suspension.growth_time_s"},
           {"--hematocrit 0.2 --set 'suspension.cells=[{\"morphology\": \"discocyte\", "
            "\"centre_um\": [2, 0, 0]}]'",
            "suspension.cells"},
           {"--set 'suspension.cells=[{\"morphology\": \"discocyte\", \"centre_um\": [2, 0, "
            "0], \"axis\": [1, 0, 0]}, {\"morphology\": \"discocyte\", \"centre_um\": [3, 0, "
            "0], \"axis\": [1, 0, 0]}]'",
            "suspension.cells: cell 0 comes closer to another cell"},
           {"--set 'suspension.cells=[{\"morphology\": \"discocyte\", \"centre_um\": [2, 0, "
            "0], \"axis\": [1, 0, 0]}]' --mix discocyte=1",
            "suspension.mix"},
       }) {
    const auto run = run_rbcsim(std::string(kCoarseTube) + arguments + " --output '" + out + "'",
                                scratch.path());
    EXPECT_EQ(run.exit_code, 2) << arguments << ": " << run.err;
    EXPECT_NE(run.err.find(named), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(fs::exists(out)) << arguments;
  }
  const auto paper =
      run_rbcsim("capillary --hematocrit 0.2 --output '" + out + "'", scratch.path());
  EXPECT_EQ(paper.exit_code, 2);
  EXPECT_NE(paper.err.find("--geometry tube"), std::string::npos) << paper.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
