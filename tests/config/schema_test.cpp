#include "config/schema.hpp"
#include "config/option_table.hpp"
#include "config/reference_page.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "config/option_table.hpp"

namespace {

using nlohmann::json;

// "membrane.k_link_kBT" -> /properties/membrane/properties/k_link_kBT
json::json_pointer schema_pointer(const std::string& path) {
  json::json_pointer pointer;
  for (const auto& segment : rbcsim::config::split_path(path))
    pointer = pointer / "properties" / segment;
  return pointer;
}

TEST(ConfigSchema, ShippedFileIsUpToDate) {
  std::ifstream stream(std::string(RBCSIM_SOURCE_DIR) + "/schemas/config.schema.json");
  std::stringstream shipped;
  shipped << stream.rdbuf();
  EXPECT_TRUE(shipped.str() == rbcsim::config::config_schema_text())
      << "schemas/config.schema.json differs from the option table; refresh it with\n"
         "  rbcsim config schema > schemas/config.schema.json";
}

TEST(ConfigReference, ShippedPageIsUpToDate) {
  std::ifstream stream(std::string(RBCSIM_SOURCE_DIR) + "/docs/configuration.md");
  std::stringstream shipped;
  shipped << stream.rdbuf();
  EXPECT_TRUE(shipped.str() == rbcsim::config::configuration_reference_markdown())
      << "docs/configuration.md differs from the option table; refresh it with\n"
         "  rbcsim config reference > docs/configuration.md";
}

TEST(ConfigReference, ListsEveryOptionOnce) {
  const auto page = rbcsim::config::configuration_reference_markdown();
  for (const auto& option : rbcsim::config::option_table().options()) {
    const auto row = "| `" + option.path + "` |";
    const auto at = page.find(row);
    EXPECT_NE(at, std::string::npos) << option.path;
    EXPECT_EQ(page.find(row, at + 1), std::string::npos) << option.path;
  }
}

TEST(ConfigSchema, DescribesEveryOptionWithTypeUnitDefaultAndRange) {
  const auto schema = rbcsim::config::config_schema();
  EXPECT_EQ(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
  EXPECT_EQ(schema["additionalProperties"], false);
  const auto& membrane = schema["properties"]["membrane"];
  EXPECT_EQ(membrane["type"], "object");
  EXPECT_EQ(membrane["additionalProperties"], false);
  const auto& k_link = membrane["properties"]["k_link_kBT"];
  EXPECT_EQ(k_link["type"], "number");
  EXPECT_EQ(k_link["default"], 7.0);
  EXPECT_EQ(k_link["minimum"], 0.0);
  EXPECT_NE(k_link["description"].get<std::string>().find("kBT"), std::string::npos);
  EXPECT_EQ(schema["properties"]["lattice"]["properties"]["relaxation_time"]["exclusiveMinimum"],
            0.5);
  const auto& subdivisions = schema["properties"]["mesh"]["properties"]["subdivisions"];
  EXPECT_EQ(subdivisions["type"], "integer");
  EXPECT_EQ(subdivisions["minimum"], 1);
  EXPECT_EQ(subdivisions["maximum"], 6);
  const auto& forces = membrane["properties"]["forces"];
  EXPECT_EQ(forces["type"], "array");
  EXPECT_EQ(forces["uniqueItems"], true);
  // The paper's six, total_area, helfrich, local_area and viscosity.
  EXPECT_EQ(forces["items"]["enum"].size(), 10u);
  EXPECT_EQ(schema["properties"]["membrane"]["properties"]["forces"]["default"].size(), 6u);
  EXPECT_EQ(schema["properties"]["morphology"]["enum"],
            json({"stomatocyte-II", "discocyte", "echinocyte-III"}));
  for (const auto& option : rbcsim::config::option_table().options()) {
    EXPECT_TRUE(schema.contains(schema_pointer(option.path))) << option.path;
  }
}

}  // namespace
