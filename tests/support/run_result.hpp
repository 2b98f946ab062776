// What a command writes as its result (result.json, and stdout with --json), held to the shipped
// contract: schemas/result.schema.json, and the printed result being the written one.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/files.hpp"
#include "support/json_schema_check.hpp"
#include "support/run_rbcsim.hpp"

namespace rbcsim::testing {

// Where `result` departs from schemas/result.schema.json ("<JSON pointer>: <what>"); empty when
// it conforms.
inline std::vector<std::string> result_schema_problems(const nlohmann::json& result) {
  const auto schema =
      read_json(std::filesystem::path(RBCSIM_SOURCE_DIR) / "schemas/result.schema.json");
  return schema_problems(result, schema);
}

// The result a successful `rbcsim <command> --json --output run_dir` printed (the caller has
// asserted exit code 0), after checking what every such run owes: the printed result equal to
// run_dir/result.json, this command, status "ok", and the result schema.
inline nlohmann::json printed_run_result(const RunResult& run, const std::filesystem::path& run_dir,
                                         const std::string& command) {
  SCOPED_TRACE("rbcsim " + command + " --json --output " + run_dir.string());
  const auto printed = nlohmann::json::parse(run.out);
  EXPECT_EQ(printed, read_json(run_dir / "result.json"));
  EXPECT_EQ(printed["command"], command);
  EXPECT_EQ(printed["status"], "ok");
  EXPECT_EQ(result_schema_problems(printed), std::vector<std::string>{});
  return printed;
}

}  // namespace rbcsim::testing
