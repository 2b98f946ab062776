// The shapes shipped in meshes/ (scripts/regenerate_meshes.sh): the paper's three morphologies,
// minimised from membrane mechanics at levels 3 and 4. The default suite checks that the files
// are the ones the binary embeds, that the default settings find them (a changed default without
// regenerated meshes fails here), and the acceptance figures of each shape; the validate target
// minimises them again and compares.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "config/config.hpp"
#include "mesh/geometry.hpp"
#include "mesh/inspection.hpp"
#include "mesh/self_intersection.hpp"
#include "setup/cell_from_config.hpp"
#include "shapes/named_cells.hpp"
#include "shapes/shape_analysis.hpp"
#include "shapes/shipped_shapes.hpp"

namespace {

namespace shapes = rbcsim::shapes;
namespace mesh = rbcsim::mesh;

const std::filesystem::path kMeshDir = std::filesystem::path(RBCSIM_SOURCE_DIR) / "meshes";
const std::string kRefresh =
    "; after an intended change of the model or a default, run scripts/regenerate_meshes.sh, "
    "rebuild and commit meshes/";
const std::set<std::string> kMorphologies = {"discocyte", "stomatocyte-II", "echinocyte-III"};

nlohmann::json manifest() {
  std::ifstream in(kMeshDir / "manifest.json");
  EXPECT_TRUE(in.good()) << "meshes/manifest.json is missing" << kRefresh;
  return nlohmann::json::parse(in);
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

shapes::NamedCellSettings default_settings(const std::string& shape, int level) {
  auto settings = rbcsim::setup::named_cell_settings_from(
      rbcsim::config::resolve_config({.morphology = shape}), shape);
  settings.method = "energy";
  settings.subdivisions = level;
  return settings;
}

TEST(ShippedShapes, ThePapersMorphologiesAreShippedAtLevelsThreeAndFourAsEmbedded) {
  std::set<std::pair<std::string, int>> listed;
  const auto listing = manifest();  // alive through the loop
  for (const auto& entry : listing["meshes"]) {
    SCOPED_TRACE(entry["output"].get<std::string>());
    EXPECT_EQ(entry["method"], "energy");
    listed.emplace(entry["shape"].get<std::string>(), entry["subdivisions"].get<int>());
    const auto embedded = rbcsim::find_embedded_file(shapes::embedded_mesh_files(),
                                                     entry["output"].get<std::string>());
    ASSERT_TRUE(embedded) << "not embedded: rebuild after regenerating";
    EXPECT_EQ(*embedded, file_bytes(kMeshDir / entry["output"].get<std::string>()))
        << "the binary embeds another version: rebuild";
  }
  for (const auto& shape : kMorphologies) {
    for (const int level : {3, 4}) {
      EXPECT_TRUE(listed.count({shape, level})) << shape << " level " << level << kRefresh;
    }
  }
}

TEST(ShippedShapes, TheDefaultSettingsFindTheShippedShapes) {
  for (const auto& shape : kMorphologies) {
    for (const int level : {3, 4}) {
      SCOPED_TRACE(shape + " level " + std::to_string(level));
      const auto cell = shapes::make_named_cell(shape, "test", default_settings(shape, level));
      EXPECT_FALSE(cell.minimised)
          << "the defaults are not the shipped shape's settings" << kRefresh;
    }
  }
}

// The acceptance figures of every shipped shape: the held reduced volume and area, a genus-0
// surface without slivers that does not pass through itself.
TEST(ShippedShapes, EveryShapeHoldsItsVolumeAndAreaAndIsAValidSurface) {
  const auto listing = manifest();  // alive through the loop
  ASSERT_EQ(listing["meshes"].size(), 6u);
  for (const auto& entry : listing["meshes"]) {
    SCOPED_TRACE(entry["output"].get<std::string>());
    const auto shipped = shapes::read_icosphere_stl(
        file_bytes(kMeshDir / entry["output"].get<std::string>()), entry["subdivisions"]);
    const auto report = mesh::inspect_mesh(shipped);
    const auto& settings = entry["settings"];
    EXPECT_NEAR(report.reduced_volume, settings["reduced_volume"].get<double>(), 0.005);
    EXPECT_NEAR(report.area_um2 / settings["membrane_area_um2"].get<double>(), 1.0, 1e-3);
    EXPECT_EQ(report.genus, 0);
    EXPECT_EQ(report.sliver_triangle_count, 0u);
    EXPECT_TRUE(mesh::self_intersections(shipped).empty());
  }
}

mesh::TriangleMesh shipped_mesh(const std::string& shape, int level) {
  auto cell = shapes::make_named_cell(shape, "test", default_settings(shape, level));
  return cell.mesh;
}

TEST(ShippedShapes, TheDiscocyteIsEvansAndFungsAndTheCupIsDeep) {
  // Evans & Fung's profile (1972, independent of the model) within 0.15 um.
  EXPECT_LT(shapes::distance_from_evans_fung(shipped_mesh("discocyte", 4)).max_um, 0.15);
  // Stomatocyte II, "a cup with a deep invagination": the cavity's depth over the diameter.
  const auto cup = shapes::measure_invagination(shipped_mesh("stomatocyte-II", 4));
  EXPECT_GT(cup.depth_to_diameter, 0.3);
  EXPECT_GT(cup.cup_offset_um, 0.5);
}

// Echinocyte III, "a sphere with regularly spaced spicules, about 30-50" (the paper; Lim 2003:
// 25-50): resolved spicules of the 2562-vertex shape (single-vertex spikes, a discretisation
// failure counted apart, are not spicules), evenly spaced, and no spikes. Measured at the default
// Delta a0, the continuation path and four seeded starts: 32 resolved spicules (spacing CV 0.075)
// and 1 spike (docs/validation.md; the stiff path's minimum had 25 and 26), so this check fails on
// the one spike; it is kept as the acceptance bound, not moved to the result.
TEST(ValidateShippedShapes, TheEchinocyteHasTwentyFiveToFiftyRegularSpicules) {
  const auto spicules = shapes::find_spicules(shipped_mesh("echinocyte-III", 4));
  EXPECT_GE(spicules.tip_vertices.size(), 25u);
  EXPECT_LE(spicules.tip_vertices.size(), 50u);
  EXPECT_LT(spicules.nearest_spacing_cv, 0.25);
  EXPECT_TRUE(spicules.spike_vertices.empty()) << spicules.spike_vertices.size() << " spikes";
}

TEST(ValidateShippedShapes, MinimisingAgainReproducesEveryShippedShape) {
  for (const auto& shape : kMorphologies) {
    for (const int level : {3, 4}) {
      SCOPED_TRACE(shape + " level " + std::to_string(level));
      auto settings = default_settings(shape, level);
      const auto shipped = shapes::make_named_cell(shape, "test", settings).mesh;
      settings.use_shipped = false;
      const auto fresh = shapes::make_named_cell(shape, "test", settings).mesh;
      double worst_um = 0.0;
      for (std::size_t v = 0; v < fresh.vertex_count(); ++v) {
        worst_um = std::max(worst_um, (fresh.positions_um[v] - shipped.positions_um[v]).norm());
      }
      // Single precision both ways; the minimiser is deterministic, so any difference comes from
      // another compiler's rounding, amplified at most to the force tolerance's displacement.
      EXPECT_LT(worst_um, 1e-4) << kRefresh;
    }
  }
}

}  // namespace
