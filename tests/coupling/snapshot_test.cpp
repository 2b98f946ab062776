// ParaView output: the files a run writes parse as XML, carry the arrays the design names, in SI
// units, and the .pvd collections list them with their times.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>

#include "coupling/coupled_simulation.hpp"
#include "coupling/snapshot.hpp"
#include "coupling_fixtures.hpp"
#include "support/files.hpp"
#include "support/scratch_directory.hpp"
#include "support/vtk_base64.hpp"
#include "support/xml_document.hpp"

namespace rbcsim::coupling {
namespace {

using testing::couette_fluid;
using testing::plasma_units;
using testing::sphere_mesh;
using testing::stretched;

// A VTK XML file parsed strictly (fails the test unless well-formed), its root element and every
// DataArray by Name.
struct VtkFile {
  rbcsim::testing::XmlDocument document;
  std::map<std::string, std::size_t> arrays;  // Name -> index in document.elements

  const rbcsim::testing::XmlElement& root() const { return document.elements.front(); }
  std::string array_text(const std::string& name) const {
    const auto found = arrays.find(name);
    EXPECT_NE(found, arrays.end()) << "no DataArray " << name;
    return found == arrays.end() ? "" : document.elements[found->second].text;
  }
  std::vector<double> doubles(const std::string& name) const {
    return rbcsim::testing::decode_vtk_binary<double>(array_text(name));
  }
};

VtkFile read_vtk(const std::filesystem::path& path) {
  VtkFile file{rbcsim::testing::parse_xml(rbcsim::testing::read_text(path)), {}};
  EXPECT_EQ(file.document.error, "") << path << " is not well-formed XML";
  for (const auto i : file.document.find("DataArray")) {
    file.arrays[file.document.elements[i].attribute("Name")] = i;
  }
  return file;
}

// A stretched capsule between moving walls after a few steps, with its output every 2 steps.
struct ShearedCapsuleRun {
  rbcsim::testing::ScratchDirectory scratch;
  std::unique_ptr<CoupledSimulation> simulation;

  ShearedCapsuleRun() {
    simulation = std::make_unique<CoupledSimulation>(couette_fluid(10, 12, 8, 0.01), plasma_units(),
                                                     CouplingParameters{});
    const Vec3 centre_um(2.3, 2.8, 1.9);
    const auto sphere = sphere_mesh(2, 1.2, centre_um);
    simulation->add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                         stretched(sphere, centre_um, Vec3(1.1, 1.0, 0.95)));
    add_vtk_output(*simulation, scratch.path(), {2, 4});
    simulation->add_stop_criterion(stop_at_time(5 * plasma_units().dt_s()));
    simulation->run();
  }
};

TEST(Snapshots, MembraneFileHasEveryForceTermTheTotalsAndTheVelocityInSI) {
  const ShearedCapsuleRun run;
  const auto& simulation = *run.simulation;
  const auto file = read_vtk(run.scratch.path() / "vtk" / "cell0_000000005.vtp");
  ASSERT_FALSE(file.document.elements.empty());
  EXPECT_EQ(file.root().attribute("type"), "PolyData");
  EXPECT_EQ(file.root().attribute("header_type"), "UInt64");
  const Cell& cell = simulation.cell(0);
  for (const auto& term : cell.membrane_forces().terms) {
    const auto values = file.doubles("force_" + term.name + "_pN");
    ASSERT_EQ(values.size(), 3 * cell.vertex_count()) << term.name;
    EXPECT_EQ(values[3], term.forces_pN[1].x()) << term.name;
  }
  EXPECT_EQ(cell.membrane_forces().terms.size(), 6u);
  const auto total = file.doubles("total_force_pN");
  ASSERT_EQ(total.size(), 3 * cell.vertex_count());
  EXPECT_EQ(total[5], cell.total_forces_pN()[1].z());
  file.array_text("membrane_force_pN");
  file.array_text("external_force_pN");
  // Velocity in m/s: lattice velocity times dx / dt.
  const double dx_per_dt = 0.5e-6 / plasma_units().dt_s();
  const auto velocity = file.doubles("velocity_m_per_s");
  ASSERT_EQ(velocity.size(), 3 * cell.vertex_count());
  EXPECT_NEAR(velocity[0], cell.velocities_lu()[0].x() * dx_per_dt, 1e-12 * dx_per_dt);
  // Points in um: the lattice positions times dx (origin at node 0).
  const auto points = file.doubles("Points");
  EXPECT_NEAR(points[4], 0.5 * cell.positions_lu()[1].y(), 1e-12);
}

TEST(Snapshots, FluidFileHasVelocityDensityAndSolidMaskOnTheLattice) {
  const ShearedCapsuleRun run;
  const auto& fluid = run.simulation->fluid();
  const auto file = read_vtk(run.scratch.path() / "vtk" / "fluid_000000004.vti");
  ASSERT_FALSE(file.document.elements.empty());
  EXPECT_EQ(file.root().attribute("type"), "ImageData");
  const auto images = file.document.find("ImageData", "", 0);
  ASSERT_EQ(images.size(), 1u);
  const auto& image = file.document.elements[images.front()];
  EXPECT_EQ(image.attribute("WholeExtent"), "0 9 0 11 0 7");
  EXPECT_EQ(image.attribute("Spacing"), "0.5 0.5 0.5");
  const auto mask = rbcsim::testing::decode_vtk_binary<std::uint8_t>(file.array_text("solid_mask"));
  EXPECT_EQ(mask, fluid.solid_mask());
  // Written at step 4, read after step 5: only the shape and units are compared.
  const auto density = file.doubles("density_kg_per_m3");
  ASSERT_EQ(density.size(), fluid.grid().node_count());
  const std::size_t middle = fluid.grid().index(5, 6, 4);
  EXPECT_NEAR(density[middle], 1025.0, 1025.0 * 1e-3);
  EXPECT_EQ(density[fluid.grid().index(5, 0, 4)], 0.0);  // a wall node
  const auto velocity = file.doubles("velocity_m_per_s");
  ASSERT_EQ(velocity.size(), 3 * fluid.grid().node_count());
  // The top wall moves at 0.01 dx/dt: its node reports that velocity.
  const double dx_per_dt = 0.5e-6 / plasma_units().dt_s();
  EXPECT_NEAR(velocity[3 * fluid.grid().index(5, 11, 4)], 0.01 * dx_per_dt, 1e-12 * dx_per_dt);
}

TEST(Snapshots, CollectionsListEverySnapshotWithItsTimeAndNoTemporaryFilesRemain) {
  const ShearedCapsuleRun run;
  const double dt_s = plasma_units().dt_s();
  const auto cells = read_vtk(run.scratch.path() / "cell0.pvd");
  ASSERT_FALSE(cells.document.elements.empty());
  std::vector<std::pair<std::string, double>> entries;
  for (const auto collection : cells.document.find("Collection", "", 0)) {
    for (const auto i : cells.document.find("DataSet", "", static_cast<long>(collection))) {
      const auto& set = cells.document.elements[i];
      entries.emplace_back(set.attribute("file"), std::stod(set.attribute("timestep")));
    }
  }
  // Initial state, every 2 steps, and the final state (step 5).
  const std::vector<std::size_t> steps = {0, 2, 4, 5};
  ASSERT_EQ(entries.size(), steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(entries[k].first, "vtk/cell0_00000000" + std::to_string(steps[k]) + ".vtp");
    EXPECT_NEAR(entries[k].second, static_cast<double>(steps[k]) * dt_s, 1e-9 * dt_s);
    EXPECT_TRUE(std::filesystem::exists(run.scratch.path() / entries[k].first));
  }
  EXPECT_TRUE(std::filesystem::exists(run.scratch.path() / "fluid.pvd"));
  for (const auto& entry : std::filesystem::recursive_directory_iterator(run.scratch.path())) {
    const auto name = entry.path().filename().string();
    EXPECT_TRUE(name.ends_with(".vtp") || name.ends_with(".vti") || name.ends_with(".pvd") ||
                entry.is_directory())
        << "left behind: " << entry.path();
  }
}

}  // namespace
}  // namespace rbcsim::coupling
