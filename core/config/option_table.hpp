// The ONE option table of rbcsim (docs/architecture.md). The parser, the defaults, `config show`
// and the JSON Schema (schemas/config.schema.json) are all derived from these rows, so an option
// exists, is documented and is validated the moment its row is added.
//
// Rows are added per area in core/config/options/<area>_options.cpp; to add an option, edit the
// file of its area. Paths are dotted ("membrane.k_link_kBT") and carry their unit in the name.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::config {

enum class OptionType {
  number,   // JSON number (double)
  integer,  // JSON integer (fits in int)
  boolean,
  string,
  choice,       // one string of `choices`
  choice_list,  // array of distinct strings, each one of `choices`
  cell_list,    // array of placed cells (kCellListFields), each morphology one of `choices`
};

// The fields of one element of a cell_list: a cell of a morphology (or of a mesh file with a
// morphology's membrane) whose centroid is placed at a point, its symmetry axis (the mesh's z)
// turned to a direction and then spun about it.
struct CellListField {
  std::string_view name;
  std::string_view json_type;  // "string", "vector" (3 finite numbers) or "number"
  bool required;
  std::string_view doc;
};
inline constexpr std::array<CellListField, 5> kCellListFields{{
    {"morphology", "string", true,
     "One of the morphologies: the cell's membrane (its Table 2 stiffnesses) and, without a "
     "mesh_file, its shape."},
    {"mesh_file", "string", false,
     "A mesh file read as mesh.file is (STL, OBJ, PLY, OFF; a path from the working "
     "directory): the cell's stress-free shape instead of the morphology's; default none."},
    {"centre_um", "vector", true, "Where the cell's centroid goes, um."},
    {"axis", "vector", false,
     "Direction the cell's symmetry axis (its mesh's z) is turned to; default [0, 0, 1]."},
    {"spin_deg", "number", false,
     "Turn about that axis after it, degrees (right-handed); default 0."},
}};

// One end of the allowed range of a number or integer.
struct Limit {
  double value;
  bool inclusive;
};

struct Option {
  std::string path;
  OptionType type;
  std::string unit;  // "" when dimensionless or not a quantity
  nlohmann::json default_value;
  std::optional<Limit> minimum;
  std::optional<Limit> maximum;
  std::vector<std::string> choices;  // for choice and choice_list
  std::string doc;                   // one line

  // Range builders, chained onto OptionTable::add_*: table.add_number(...).above(0.5).
  Option& above(double value);     // > value
  Option& at_least(double value);  // >= value
  Option& below(double value);     // < value
  Option& at_most(double value);   // <= value
};

class OptionTable {
 public:
  // Each returns the new row so that a range can be chained onto it. Throws std::logic_error for
  // a duplicate path or a path that is both an option and a group of options.
  Option& add_number(std::string path, std::string unit, double default_value, std::string doc);
  Option& add_integer(std::string path, std::string unit, int default_value, std::string doc);
  Option& add_boolean(std::string path, bool default_value, std::string doc);
  Option& add_string(std::string path, std::string default_value, std::string doc);
  Option& add_choice(std::string path, std::vector<std::string> choices, std::string default_value,
                     std::string doc);
  Option& add_choice_list(std::string path, std::vector<std::string> choices,
                          std::vector<std::string> default_value, std::string doc);
  // Default: the empty list.
  Option& add_cell_list(std::string path, std::vector<std::string> morphologies, std::string doc);

  const std::vector<Option>& options() const { return options_; }
  // The row of an option path, or nullptr.
  const Option* find(std::string_view path) const;
  // True for a proper prefix of option paths ("membrane" for "membrane.k_link_kBT").
  bool is_group(std::string_view path) const;
  // Every option path and every group path: the candidates of "did you mean".
  std::vector<std::string> known_paths() const;
  // The nested tree of all defaults.
  nlohmann::json defaults() const;

 private:
  Option& add(Option option);

  std::vector<Option> options_;
};

// The project's table, built once from every area file; each default is checked against its own
// row (a wrong row is a programming error: std::logic_error).
const OptionTable& option_table();

// Top-level keys a config file may hold besides options. `$schema` lets editors find the schema
// and autocomplete; `derived` is what `config show` and a run's config.json print beside the
// options (dt, lattice viscosity, ...): it is recomputed, so on input it is accepted and ignored.
// That way the output of `config show` can be passed back with --config.
struct AnnotationKey {
  std::string_view name;
  std::string_view json_type;
  std::string_view doc;
};
inline constexpr std::array<AnnotationKey, 2> kAnnotationKeys{{
    {"$schema", "string", "URI of this file's JSON Schema, for editors; ignored by rbcsim."},
    {"derived", "object",
     "Values derived from the options (lattice scales in SI); written by rbcsim, ignored on "
     "input."},
}};
const AnnotationKey* find_annotation_key(std::string_view name);

// Splits "a.b.c" at the dots.
std::vector<std::string> split_path(std::string_view path);
// "a.b.c" as the JSON pointer "/a/b/c".
nlohmann::json::json_pointer json_pointer(std::string_view path);

}  // namespace rbcsim::config
