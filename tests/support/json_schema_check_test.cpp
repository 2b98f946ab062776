// The tests' JSON Schema check itself: a "$ref" holds the document to the definition it names,
// so a schema that shares one definition between commands checks both.
#include "support/json_schema_check.hpp"

#include <gtest/gtest.h>

namespace rbcsim::testing {
namespace {

using nlohmann::json;

const json kSchema = json::parse(R"({
  "$defs": {"count": {"type": "integer", "minimum": 0}},
  "type": "object",
  "properties": {"a": {"$ref": "#/$defs/count"}, "b": {"type": "string"}}
})");

TEST(JsonSchemaCheck, AReferenceChecksTheDefinitionItNames) {
  EXPECT_EQ(schema_problems(json{{"a", 3}, {"b", "x"}}, kSchema), std::vector<std::string>{});
  EXPECT_EQ(schema_problems(json{{"a", -1}}, kSchema),
            std::vector<std::string>{"/a: below the minimum"});
  EXPECT_EQ(schema_problems(json{{"a", "three"}}, kSchema),
            std::vector<std::string>{"/a: not of type \"integer\""});
}

TEST(JsonSchemaCheck, AReferenceOutsideTheDocumentIsRefused) {
  const json schema = {{"$ref", "other.json#/x"}};
  EXPECT_THROW(schema_problems(json{}, schema), std::invalid_argument);
  const json dangling = {{"$ref", "#/$defs/missing"}};
  EXPECT_THROW(schema_problems(json{}, dangling), json::out_of_range);
}

}  // namespace
}  // namespace rbcsim::testing
