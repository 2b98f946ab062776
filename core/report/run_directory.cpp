#include "report/run_directory.hpp"

#include <algorithm>
#include <array>

#include "common/errors.hpp"
#include "membrane/parameters.hpp"

namespace rbcsim::report {
namespace {

constexpr std::string_view kConfigFile = "config.json";
constexpr std::string_view kResultFile = "result.json";

// "a", "a and b", "a, b and c".
std::string join_words(const std::vector<std::string>& words) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += i + 1 == words.size() ? " and " : ", ";
    joined += words[i];
  }
  return joined;
}

std::string count_in_words(std::size_t count) {
  constexpr std::array<std::string_view, 13> kWords{"no",   "one",    "two",   "three", "four",
                                                    "five", "six",    "seven", "eight", "nine",
                                                    "ten",  "eleven", "twelve"};
  return count < kWords.size() ? std::string(kWords[count]) : std::to_string(count);
}

std::vector<std::string> string_list(const JsonField& field) {
  std::vector<std::string> items;
  for (std::size_t i = 0; i < field.array_size(); ++i) items.push_back(field.at(i).string());
  return items;
}

}  // namespace

// Relative to the paper's six: "all six", "without area_difference and total_curvature", and the
// terms beyond them appended ("all six + total_area", "without bend, with helfrich").
std::string describe_terms(const std::vector<std::string>& enabled) {
  const auto paper = membrane::paper_force_term_names();
  const auto all = membrane::all_force_term_names();
  const auto contains = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  if (!std::all_of(enabled.begin(), enabled.end(),
                   [&](const std::string& name) { return contains(all, name); })) {
    return join_words(enabled);
  }
  std::vector<std::string> missing;
  for (const auto& name : paper) {
    if (!contains(enabled, name)) missing.push_back(name);
  }
  std::vector<std::string> extra;
  for (const auto& name : enabled) {
    if (!contains(paper, name)) extra.push_back(name);
  }
  std::string described = missing.empty()                  ? "all " + count_in_words(paper.size())
                          : missing.size() == paper.size() ? "none of the paper's"
                                                           : "without " + join_words(missing);
  // "without bend, with helfrich": "without bend + helfrich" reads as if both were left out.
  if (!extra.empty()) described += (missing.empty() ? " + " : ", with ") + join_words(extra);
  return described;
}

JsonField RunDirectory::config_field() const {
  return JsonField(config, (directory / kConfigFile).string());
}

JsonField RunDirectory::result_field() const {
  return JsonField(result, (directory / kResultFile).string());
}

RunDirectory read_run_directory(const std::filesystem::path& directory) {
  if (!std::filesystem::exists(directory))
    throw InputError(directory.string(), "no such directory");
  if (!std::filesystem::is_directory(directory)) {
    throw InputError(directory.string(), "not a directory (expected a run directory)");
  }
  RunDirectory run;
  run.directory = directory;
  run.config = read_json_file(directory / kConfigFile);
  run.result = read_json_file(directory / kResultFile);

  const auto result = run.result_field();
  run.command = result.at("command").string();
  // A capillary suspension (result.json's "suspension" object) is an experiment of its own: the
  // capillary section reads one cell's transit. It is reported under "suspension".
  if (run.command == "capillary" && run.result.contains("suspension")) run.command = "suspension";
  // Likewise a sheared suspension (`shear --hematocrit`): its relative viscosity per rate, not one
  // cell's length.
  if (run.command == "shear" && run.result.contains("sheared_suspension")) {
    run.command = "sheared_suspension";
  }
  run.morphology = result.at("morphology").string();
  run.status = result.at("status").string();
  if (run.status != "ok" && run.status != "failed" && run.status != "interrupted") {
    result.at("status").fail("expected \"ok\", \"failed\" or \"interrupted\", found \"" +
                             run.status + "\"");
  }
  result.at("version").string();
  result.at("wall_time_s").number();
  result.at("threads").integer();
  result.at("headline").object();

  run.forces = string_list(run.config_field().at("membrane").at("forces"));
  const auto preset = run.config_field().find("preset");
  run.preset = preset ? preset->string() : "-";
  run.terms = describe_terms(run.forces);
  // Older run directories have no run.notices: none told.
  if (const auto run_object = run.config_field().find("run")) {
    if (const auto notices = run_object->find("notices")) run.notices = string_list(*notices);
  }
  return run;
}

}  // namespace rbcsim::report
