#include "config/config.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/errors.hpp"
#include "config/config_sources.hpp"
#include "config/embedded_share.hpp"
#include "config/option_table.hpp"
#include "config/validation.hpp"

namespace rbcsim::config {
namespace {

using nlohmann::json;

constexpr std::string_view kMorphologyPath = "morphology";
constexpr std::string_view kPresetPath = "preset";

struct ConfigLayer {
  std::string source;
  json tree;
};

// Deep merge: objects merge key by key, anything else (numbers, strings, lists) is replaced.
void merge_into(json& base, const json& layer) {
  for (const auto& [key, value] : layer.items()) {
    if (value.is_object() && base.contains(key) && base[key].is_object()) {
      merge_into(base[key], value);
    } else {
      base[key] = value;
    }
  }
}

json without_annotations(json tree) {
  for (const auto& annotation : kAnnotationKeys) tree.erase(std::string(annotation.name));
  return tree;
}

std::vector<ConfigLayer> user_layers(const ConfigRequest& request) {
  std::vector<ConfigLayer> layers;
  for (const auto& file : request.files) layers.push_back({file.string(), read_config_file(file)});
  for (const auto& assignment : request.assignments) {
    layers.push_back({"--set", parse_assignment(assignment)});
  }
  for (const auto& [option, assignment] : request.option_assignments) {
    layers.push_back({option, parse_assignment(assignment, option)});
  }
  return layers;
}

// The value of a top-level choice that selects an overlay (morphology, preset): the command
// option if given, else the last layer that sets it, else its default.
std::string chosen(std::string_view path, const std::optional<std::string>& from_option,
                   std::string_view option_name, const std::vector<ConfigLayer>& layers) {
  const auto& option = *option_table().find(path);
  if (from_option) {
    if (const auto problem = value_problem(option, *from_option)) {
      throw InputError(std::string(option_name), *problem);
    }
    return *from_option;
  }
  const std::string key(path);
  const auto last = std::find_if(layers.rbegin(), layers.rend(), [&key](const ConfigLayer& layer) {
    return layer.tree.contains(key);
  });
  return last != layers.rend() ? last->tree[key].get<std::string>()
                               : option.default_value.get<std::string>();
}

json share_overlay(const std::string& relative_path) {
  const auto text = find_embedded_share_file(relative_path);
  if (!text) throw std::logic_error("share/" + relative_path + " is not embedded in the binary");
  return without_annotations(parse_config_text(*text, "share/" + relative_path + " (embedded)"));
}

}  // namespace

Config resolve_config(const ConfigRequest& request) {
  const auto layers = user_layers(request);
  const auto morphology = chosen(kMorphologyPath, request.morphology, "--morphology", layers);
  const auto preset = chosen(kPresetPath, request.preset, "--preset", layers);
  auto tree = option_table().defaults();
  merge_into(tree, share_overlay("config/presets/" + preset + ".json"));
  merge_into(tree, share_overlay("config/" + morphology + ".json"));
  for (const auto& layer : layers) merge_into(tree, without_annotations(layer.tree));
  tree[std::string(kMorphologyPath)] = morphology;
  tree[std::string(kPresetPath)] = preset;
  return Config(std::move(tree));
}

const json& Config::value(std::string_view path, std::initializer_list<OptionType> readable_types,
                          std::string_view read_as) const {
  const auto* option = option_table().find(path);
  if (!option) throw std::logic_error("config: no option `" + std::string(path) + "`");
  if (std::find(readable_types.begin(), readable_types.end(), option->type) ==
      readable_types.end()) {
    throw std::logic_error("config: option `" + std::string(path) + "` cannot be read as " +
                           std::string(read_as));
  }
  return tree_.at(json_pointer(path));
}

Config Config::with(std::string_view path, const nlohmann::json& value) const {
  const auto* option = option_table().find(path);
  if (!option) throw std::logic_error("config: no option `" + std::string(path) + "`");
  if (const auto problem = value_problem(*option, value)) {
    throw std::logic_error("config: derived `" + std::string(path) + "`: " + *problem);
  }
  auto tree = tree_;
  tree[json_pointer(path)] = value;
  return Config(std::move(tree));
}

double Config::number(std::string_view path) const {
  return value(path, {OptionType::number, OptionType::integer}, "number").get<double>();
}

int Config::integer(std::string_view path) const {
  return value(path, {OptionType::integer}, "integer").get<int>();
}

bool Config::boolean(std::string_view path) const {
  return value(path, {OptionType::boolean}, "boolean").get<bool>();
}

std::string Config::string(std::string_view path) const {
  return value(path, {OptionType::string, OptionType::choice}, "string").get<std::string>();
}

std::vector<std::string> Config::string_list(std::string_view path) const {
  return value(path, {OptionType::choice_list}, "string list").get<std::vector<std::string>>();
}

std::vector<CellPlacement> Config::cell_list(std::string_view path) const {
  std::vector<CellPlacement> cells;
  for (const auto& cell : value(path, {OptionType::cell_list}, "cell list")) {
    CellPlacement placement;
    placement.morphology = cell.at("morphology").get<std::string>();
    placement.mesh_file = cell.value("mesh_file", std::string());
    placement.centre_um = cell.at("centre_um").get<std::array<double, 3>>();
    if (cell.contains("axis")) placement.axis = cell.at("axis").get<std::array<double, 3>>();
    placement.spin_deg = cell.value("spin_deg", 0.0);
    cells.push_back(std::move(placement));
  }
  return cells;
}

units::UnitConverter make_unit_converter(const Config& config) {
  return units::UnitConverter({
      .spacing_um = config.number("lattice.spacing_um"),
      .relaxation_time = config.number("lattice.relaxation_time"),
      .density_kg_per_m3 = config.number("physics.plasma_density_kg_per_m3"),
      .kinematic_viscosity_m2_per_s = config.number("physics.plasma_kinematic_viscosity_m2_per_s"),
  });
}

json config_with_derived_values(const Config& config) {
  auto tree = config.json();
  auto& derived = tree["derived"];
  derived = json::object();
  for (const auto& [name, value] : make_unit_converter(config).derived_values())
    derived[name] = value;
  return tree;
}

}  // namespace rbcsim::config
