#include "bench_reference.hpp"

#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "common/errors.hpp"
#include "common_options.hpp"
#include "config/config_sources.hpp"
#include "config/embedded_share.hpp"
#include "io/text_file.hpp"

namespace rbcsim::cli {
namespace {

using nlohmann::json;

constexpr std::string_view kShippedReference = "reference/hemocell_bench.json";

std::string required_string(const json& tree, const char* key, std::string_view source) {
  if (!tree.contains(key)) throw InputError(std::string(source), std::string(key) + ": missing");
  if (!tree.at(key).is_string() || tree.at(key).get<std::string>().empty()) {
    throw InputError(std::string(source), std::string(key) + ": expected a non-empty string");
  }
  return tree.at(key).get<std::string>();
}

std::map<int, double> figures_per_thread_count(const json& tree, const char* key,
                                               std::string_view source) {
  std::map<int, double> figures;
  if (!tree.contains(key)) return figures;
  const auto& object = tree.at(key);
  if (!object.is_object()) {
    throw InputError(std::string(source), std::string(key) +
                                              ": expected an object from thread "
                                              "counts (\"1\", \"2\") to numbers");
  }
  for (const auto& [threads, value] : object.items()) {
    const std::string path = std::string(key) + "." + threads;
    const auto count = whole_number(threads);
    if (!count || *count < 1 || *count > std::numeric_limits<int>::max()) {
      throw InputError(std::string(source), path + ": a thread count must be a whole number >= 1");
    }
    if (!value.is_number() || !(value.get<double>() > 0.0)) {
      throw InputError(std::string(source), path + ": expected a positive number");
    }
    figures[static_cast<int>(*count)] = value.get<double>();
  }
  return figures;
}

std::optional<double> figure_at(const std::map<int, double>& figures, int threads) {
  const auto found = figures.find(threads);
  if (found == figures.end()) return std::nullopt;
  return found->second;
}

}  // namespace

std::optional<double> BenchReference::coupled_ms(int threads) const {
  return figure_at(coupled_ms_per_step_642_vertices, threads);
}

std::optional<double> BenchReference::fluid_mlups(int threads) const {
  return figure_at(fluid_mlups_40x40x20, threads);
}

BenchReference parse_bench_reference(std::string_view text, std::string_view source) {
  const json tree = config::parse_json(text, source);
  if (!tree.is_object()) throw InputError(std::string(source), "expected a JSON object");
  static const std::set<std::string> kKeys = {
      "label", "machine", "provenance", "coupled_ms_per_step_642_vertices", "fluid_mlups_40x40x20"};
  for (const auto& [key, value] : tree.items()) {
    if (!kKeys.contains(key)) {
      throw InputError(std::string(source),
                       key +
                           ": unknown key (label, machine, provenance, "
                           "coupled_ms_per_step_642_vertices, fluid_mlups_40x40x20)");
    }
  }
  BenchReference reference;
  reference.label = required_string(tree, "label", source);
  reference.machine = required_string(tree, "machine", source);
  if (tree.contains("provenance")) {
    reference.provenance = required_string(tree, "provenance", source);
  }
  reference.coupled_ms_per_step_642_vertices =
      figures_per_thread_count(tree, "coupled_ms_per_step_642_vertices", source);
  reference.fluid_mlups_40x40x20 = figures_per_thread_count(tree, "fluid_mlups_40x40x20", source);
  return reference;
}

BenchReference load_bench_reference(const std::optional<std::filesystem::path>& file) {
  if (file) return parse_bench_reference(io::read_text_file(*file), file->string());
  const auto shipped = config::find_embedded_share_file(kShippedReference);
  if (!shipped) throw std::logic_error("share/reference/hemocell_bench.json is not embedded");
  return parse_bench_reference(*shipped, "share/reference/hemocell_bench.json");
}

}  // namespace rbcsim::cli
