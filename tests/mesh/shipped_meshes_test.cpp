// The meshes shipped in meshes/ must be what the generators make today (meshes/README.md): each is
// regenerated and compared corner by corner, and the manifest's statistics must match.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "mesh/cell_shapes.hpp"
#include "mesh/import.hpp"
#include "mesh/inspection.hpp"

namespace {

using namespace rbcsim::mesh;

const std::filesystem::path kMeshDir = std::filesystem::path(RBCSIM_SOURCE_DIR) / "meshes";
const std::string kRefresh =
    "; if the generator change is intended, run scripts/regenerate_meshes.sh build/cli/rbcsim "
    "and commit meshes/";

nlohmann::json manifest() {
  std::ifstream in(kMeshDir / "manifest.json");
  EXPECT_TRUE(in.good()) << "meshes/manifest.json is missing" << kRefresh;
  return nlohmann::json::parse(in);
}

TEST(ShippedMeshes, ManifestListsEveryShapeAtLevelsThreeAndFour) {
  const auto listing = manifest();
  std::set<std::pair<std::string, int>> listed;
  for (const auto& entry : listing["meshes"]) {
    listed.emplace(entry["shape"].get<std::string>(), entry["subdivisions"].get<int>());
  }
  for (const auto& shape : cell_shapes()) {
    for (int level : {3, 4}) {
      EXPECT_TRUE(listed.count({std::string(shape.name), level}))
          << shape.name << " level " << level << " is not shipped" << kRefresh;
    }
  }
}

TEST(ShippedMeshes, EachMatchesItsGeneratorAndItsManifestEntry) {
  const auto listing = manifest();
  for (const auto& entry : listing["meshes"]) {
    const auto file = kMeshDir / entry["output"].get<std::string>();
    SCOPED_TRACE(file.string());
    const auto generated = generate_cell(entry["shape"].get<std::string>(), entry["subdivisions"]);
    const auto shipped = import_mesh(file).mesh;
    ASSERT_EQ(shipped.triangle_count(), generated.triangle_count()) << kRefresh;
    ASSERT_EQ(shipped.vertex_count(), generated.vertex_count()) << kRefresh;
    double worst_um = 0.0;
    for (std::size_t t = 0; t < generated.triangle_count(); ++t) {
      for (int k = 0; k < 3; ++k) {
        worst_um = std::max(worst_um, (shipped.positions_um[shipped.triangles[t][k]] -
                                       generated.positions_um[generated.triangles[t][k]])
                                          .norm());
      }
    }
    // float32 storage rounds coordinates of ~4 um by ~2e-7 um.
    EXPECT_LT(worst_um, 1e-5) << "shipped mesh differs from the generator by " << worst_um << " um"
                              << kRefresh;
    const auto fresh = to_json(inspect_mesh(generated));
    const auto& listed = entry["report"];
    for (const char* key : {"area_um2", "volume_um3", "reduced_volume"}) {
      EXPECT_NEAR(listed["size"][key].get<double>(), fresh["size"][key].get<double>(),
                  1e-9 * std::abs(fresh["size"][key].get<double>()))
          << key << " in meshes/manifest.json is stale" << kRefresh;
    }
    EXPECT_EQ(listed["counts"], fresh["counts"]) << kRefresh;
  }
}

}  // namespace
