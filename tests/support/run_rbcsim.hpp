// Runs the built rbcsim binary (RBCSIM_BINARY) for CLI integration tests and captures what a
// user would see: exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace rbcsim::testing {

struct RunResult {
  int exit_code;
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

// A JSON file the binary wrote (result.json, config.json, ...).
inline nlohmann::json read_json(const std::filesystem::path& file) {
  return nlohmann::json::parse(read_text(file));
}

// `arguments` is appended to the binary's path as written, shell quoting included. Output goes
// through files in `scratch` (a directory the test owns).
inline RunResult run_rbcsim(const std::string& arguments, const std::filesystem::path& scratch) {
  const auto out = scratch / "stdout.txt";
  const auto err = scratch / "stderr.txt";
  const std::string command = std::string("'") + RBCSIM_BINARY + "' " + arguments + " >'" +
                              out.string() + "' 2>'" + err.string() + "' </dev/null";
  const int status = std::system(command.c_str());
  const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return {exit_code, read_text(out), read_text(err)};
}

}  // namespace rbcsim::testing
