#include "geometry/wall_registry.hpp"

#include <array>
#include <optional>

#include "common/errors.hpp"
#include "common/registry.hpp"
#include "geometry/capillary_wall.hpp"
#include "geometry/channel_wall.hpp"
#include "geometry/stl_wall.hpp"
#include "geometry/tube_wall.hpp"

namespace rbcsim::geometry {
namespace {

std::unique_ptr<WallShape> read_channel(ParameterReader& parameters, const MeshLoader&) {
  ChannelParameters channel;
  channel.gap_um = parameters.number("gap_um");
  channel.length_um = parameters.number("length_um");
  channel.width_um = parameters.number("width_um");
  return std::make_unique<ChannelWall>(channel, parameters.json_path());
}

std::unique_ptr<WallShape> read_tube(ParameterReader& parameters, const MeshLoader&) {
  TubeParameters tube;
  tube.diameter_um = parameters.number("diameter_um");
  tube.length_um = parameters.number("length_um");
  return std::make_unique<TubeWall>(tube, parameters.json_path());
}

// Every parameter of a preset may be overridden; without a preset the four main ones are
// required and the outlet diameter defaults to the inlet's.
std::unique_ptr<WallShape> read_capillary_over(ParameterReader& parameters,
                                               const std::optional<CapillaryParameters>& preset) {
  const auto from_preset = [&preset](double CapillaryParameters::*field) {
    return preset ? std::optional<double>((*preset).*field) : std::nullopt;
  };
  CapillaryParameters capillary;
  capillary.length_um =
      parameters.number("length_um", from_preset(&CapillaryParameters::length_um));
  capillary.inlet_diameter_um =
      parameters.number("inlet_diameter_um", from_preset(&CapillaryParameters::inlet_diameter_um));
  capillary.outlet_diameter_um = parameters.number(
      "outlet_diameter_um", preset ? preset->outlet_diameter_um : capillary.inlet_diameter_um);
  capillary.throat_diameter_um = parameters.number(
      "throat_diameter_um", from_preset(&CapillaryParameters::throat_diameter_um));
  const auto or_preset = [&preset](std::optional<double> value,
                                   std::optional<double> CapillaryParameters::*field) {
    return value || !preset ? value : (*preset).*field;
  };
  capillary.constriction_length_um = or_preset(parameters.optional_number("constriction_length_um"),
                                               &CapillaryParameters::constriction_length_um);
  capillary.constriction_centre_um = or_preset(parameters.optional_number("constriction_centre_um"),
                                               &CapillaryParameters::constriction_centre_um);
  capillary.profile = parameters.text("profile", preset ? preset->profile : capillary.profile);
  return std::make_unique<CapillaryWall>(capillary, parameters.json_path());
}

std::unique_ptr<WallShape> read_capillary(ParameterReader& parameters, const MeshLoader&) {
  return read_capillary_over(parameters, std::nullopt);
}

std::unique_ptr<WallShape> read_paper_validation(ParameterReader& parameters, const MeshLoader&) {
  return read_capillary_over(parameters, paper_validation_capillary());
}

std::unique_ptr<WallShape> read_paper_morphology(ParameterReader& parameters, const MeshLoader&) {
  return read_capillary_over(parameters, paper_morphology_capillary());
}

std::array<bool, 3> read_open_axes(ParameterReader& parameters) {
  std::array<bool, 3> open_axes{false, false, false};
  for (const auto& axis : parameters.text_list("open_axes")) {
    if (axis != "x" && axis != "y" && axis != "z") {
      throw InputError(parameter_path(parameters.json_path(), "open_axes"),
                       "unknown axis \"" + axis + "\" (x, y or z)");
    }
    open_axes[static_cast<std::size_t>(axis[0] - 'x')] = true;
  }
  return open_axes;
}

std::unique_ptr<WallShape> read_stl(ParameterReader& parameters, const MeshLoader& load_mesh) {
  const auto file = parameters.text("file");
  const auto open_axes = read_open_axes(parameters);
  if (!load_mesh) {
    throw InputError(parameter_path(parameters.json_path(), "file"),
                     "this command cannot read wall surface files");
  }
  return std::make_unique<StlWall>(load_mesh(file), open_axes, file);
}

constexpr std::array kWallShapeKinds{
    WallShapeKind{"channel",
                  "two parallel plates normal to y at y = +-gap/2, open along x and z: gap_um, "
                  "length_um (x), width_um (z)",
                  read_channel},
    WallShapeKind{"tube", "straight circular tube along x: diameter_um, length_um", read_tube},
    WallShapeKind{"capillary",
                  "circular tube along x with a smooth constriction: length_um, "
                  "inlet_diameter_um, outlet_diameter_um (default: inlet), throat_diameter_um, "
                  "constriction_length_um (default: length/3), constriction_centre_um (default: "
                  "length/2), profile (cosine | linear; default cosine)",
                  read_capillary},
    WallShapeKind{"paper-validation",
                  "the capillary of the paper's validation case: 31.2 um long, diameter 10.2 um, "
                  "throat 6.75 um; any capillary parameter may override",
                  read_paper_validation},
    WallShapeKind{"paper-morphology",
                  "the capillary of the paper's three-morphology case: 42 um long, diameter 10 um, "
                  "throat 6.8 um; any capillary parameter may override",
                  read_paper_morphology},
    WallShapeKind{"stl",
                  "a closed surface, fluid inside: file (read by the mesh importer), open_axes "
                  "(axes along which the fluid leaves the surface's box, e.g. [\"x\"])",
                  read_stl},
};

}  // namespace

std::span<const WallShapeKind> wall_shape_kinds() { return kWallShapeKinds; }

std::vector<std::string> paper_capillary_names() {
  std::vector<std::string> names;
  for (const auto& kind : kWallShapeKinds) {
    if (kind.name.starts_with("paper-")) names.emplace_back(kind.name);
  }
  return names;
}

std::unique_ptr<WallShape> make_wall_shape(std::string_view name, const nlohmann::json& parameters,
                                           std::string_view json_path,
                                           const MeshLoader& load_mesh) {
  const auto& kind = find_entry(wall_shape_kinds(), name, json_path);
  ParameterReader reader(parameters, std::string(json_path));
  auto shape = kind.read(reader, load_mesh);
  reader.reject_unread_keys();
  return shape;
}

}  // namespace rbcsim::geometry
