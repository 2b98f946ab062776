// The resolved configuration of a run and its typed read API.
//
// Resolution order (later wins): the option table's defaults <- the morphology's overlay
// share/config/<morphology>.json (embedded; Table 2 stiffnesses) <- each --config file in order
// <- each --set key.path=value in order. The morphology is --morphology if given, else the last
// file or --set that sets `morphology`, else the default. Every source is validated on its own,
// so a diagnostic names the file (or "--set") and the JSON path.
#pragma once

#include <array>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/option_table.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::config {

// A command's own option that stands for a config key (--geometry for capillary.geometry).
struct OptionAssignment {
  std::string option;      // as typed ("--geometry"): it names the value in every diagnostic
  std::string assignment;  // "capillary.geometry=paper-validation"
};

struct ConfigRequest {
  // Default member initialisers let callers name only what they set: {.morphology = "..."}.
  std::optional<std::string> morphology = {};             // --morphology: wins over files and --set
  std::optional<std::string> preset = {};                 // --preset: wins over files and --set
  std::vector<std::filesystem::path> files = {};          // --config, applied in order
  std::vector<std::string> assignments = {};              // --set key.path=value, after the files
  std::vector<OptionAssignment> option_assignments = {};  // a command's options, after --set
};

class Config;

// One element of a cell_list option (option_table.hpp, kCellListFields), defaults filled in.
struct CellPlacement {
  std::string morphology;
  std::string mesh_file;  // empty: the morphology's own shape
  std::array<double, 3> centre_um{};
  std::array<double, 3> axis{0.0, 0.0, 1.0};  // not normalised
  double spin_deg = 0.0;
};

// Throws InputError for unreadable files, JSON syntax errors, unknown keys, wrong types and
// values out of range.
Config resolve_config(const ConfigRequest& request = {});

class Config {
 public:
  // Typed reads by dotted path. Asking for a path that is not in the option table, or with the
  // wrong type, is a programming error: std::logic_error.
  double number(std::string_view path) const;  // number and integer options
  int integer(std::string_view path) const;
  bool boolean(std::string_view path) const;
  std::string string(std::string_view path) const;                    // string and choice options
  std::vector<std::string> string_list(std::string_view path) const;  // choice lists
  std::vector<CellPlacement> cell_list(std::string_view path) const;

  // A copy with the option at `path` set to `value`: for settings a command derives from the
  // user's (the capillary's time-scale compression). Throws std::logic_error for a path that is
  // not an option or a value its row refuses (a derived value out of range is a programming
  // error, the user's values having been checked).
  Config with(std::string_view path, const nlohmann::json& value) const;

  // The whole resolved tree: every option, nested by path.
  const nlohmann::json& json() const { return tree_; }

 private:
  friend Config resolve_config(const ConfigRequest& request);
  explicit Config(nlohmann::json tree) : tree_(std::move(tree)) {}
  const nlohmann::json& value(std::string_view path,
                              std::initializer_list<OptionType> readable_types,
                              std::string_view read_as) const;

  nlohmann::json tree_;
};

// The lattice units of this configuration (lattice.spacing_um, lattice.relaxation_time,
// physics.plasma_*); throws InputError for unsafe values.
units::UnitConverter make_unit_converter(const Config& config);

// The resolved tree plus a "derived" object of the unit converter's derived values: what
// `config show` prints and a run's config.json starts from. Readable back with --config.
nlohmann::json config_with_derived_values(const Config& config);

}  // namespace rbcsim::config
