// ParaView output: the files a run writes parse as XML, carry the arrays the design names, in SI
// units, and the .pvd collections list them with their times.
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <map>
#include <memory>
#include <string>

#include "coupling/coupled_simulation.hpp"
#include "coupling/snapshot.hpp"
#include "coupling_fixtures.hpp"
#include "support/scratch_directory.hpp"
#include "support/vtk_base64.hpp"

namespace rbcsim::coupling {
namespace {

using testing::couette_fluid;
using testing::plasma_units;
using testing::sphere_mesh;
using testing::stretched;

struct XmlDocumentDeleter {
  void operator()(xmlDoc* document) const { xmlFreeDoc(document); }
};
using XmlDocument = std::unique_ptr<xmlDoc, XmlDocumentDeleter>;

std::string attribute(const xmlNode* node, const char* name) {
  xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (value == nullptr) return {};
  std::string text(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return text;
}

std::string content(const xmlNode* node) {
  xmlChar* value = xmlNodeGetContent(node);
  std::string text(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return text;
}

bool named(const xmlNode* node, const char* name) {
  return node->type == XML_ELEMENT_NODE &&
         xmlStrcmp(node->name, reinterpret_cast<const xmlChar*>(name)) == 0;
}

// A VTK XML file read with libxml2: its root element and every DataArray by Name.
struct VtkFile {
  XmlDocument document;
  const xmlNode* root = nullptr;
  std::map<std::string, const xmlNode*> arrays;

  const xmlNode* array(const std::string& name) const {
    const auto found = arrays.find(name);
    EXPECT_NE(found, arrays.end()) << "no DataArray " << name;
    return found == arrays.end() ? nullptr : found->second;
  }
  std::vector<double> doubles(const std::string& name) const {
    return rbcsim::testing::decode_vtk_binary<double>(content(array(name)));
  }
};

void collect_arrays(const xmlNode* node, VtkFile& file) {
  for (; node != nullptr; node = node->next) {
    if (named(node, "DataArray")) file.arrays[attribute(node, "Name")] = node;
    collect_arrays(node->children, file);
  }
}

// Fails the test unless the file is well-formed XML.
VtkFile read_vtk(const std::filesystem::path& path) {
  VtkFile file;
  file.document.reset(xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_HUGE));
  EXPECT_TRUE(file.document) << path << " is not well-formed XML";
  if (!file.document) return file;
  file.root = xmlDocGetRootElement(file.document.get());
  collect_arrays(file.root, file);
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
  ASSERT_TRUE(file.root);
  EXPECT_EQ(attribute(file.root, "type"), "PolyData");
  EXPECT_EQ(attribute(file.root, "header_type"), "UInt64");
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
  file.array("membrane_force_pN");
  file.array("external_force_pN");
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
  ASSERT_TRUE(file.root);
  EXPECT_EQ(attribute(file.root, "type"), "ImageData");
  const xmlNode* image = file.root->children;
  while (image != nullptr && !named(image, "ImageData")) image = image->next;
  ASSERT_NE(image, nullptr);
  EXPECT_EQ(attribute(image, "WholeExtent"), "0 9 0 11 0 7");
  EXPECT_EQ(attribute(image, "Spacing"), "0.5 0.5 0.5");
  const auto mask =
      rbcsim::testing::decode_vtk_binary<std::uint8_t>(content(file.array("solid_mask")));
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
  ASSERT_TRUE(cells.root);
  std::vector<std::pair<std::string, double>> entries;
  for (const xmlNode* node = cells.root->children; node != nullptr; node = node->next) {
    if (!named(node, "Collection")) continue;
    for (const xmlNode* set = node->children; set != nullptr; set = set->next) {
      if (named(set, "DataSet")) {
        entries.emplace_back(attribute(set, "file"), std::stod(attribute(set, "timestep")));
      }
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
